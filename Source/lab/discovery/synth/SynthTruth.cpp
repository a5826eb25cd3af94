#include "lab/discovery/synth/SynthTruth.h"

namespace rosin::discovery
{

using Json = nlohmann::ordered_json;

namespace
{
Json parameterJson(const HiddenEffect& hidden)
{
    Json parameters = Json::object();
    for (std::size_t i = 0; i < hidden.effect->parameters.size(); ++i)
    {
        const auto& p = hidden.effect->parameters[i];
        if (p.choices.empty())
            parameters[p.name] = hidden.values[i];
        else
            parameters[p.name] = p.choices[static_cast<std::size_t>(hidden.values[i])];
    }
    return parameters;
}

Json trialJson(const Trial& nominal, const TrialSettings& actual, const std::optional<TrialFault>& fault)
{
    Json t;
    t["id"] = nominal.id;
    t["bowForce"] = actual.bowForce;
    if (const auto* a = std::get_if<ConstantAcceleration>(&actual.gesture))
        t["acceleration"] = a->acceleration;
    else if (const auto* s = std::get_if<Steady>(&actual.gesture))
        t["speed"] = s->speed;
    if (fault)
        t["fault"] = describeTrialFault(*fault);
    return t;
}
} // namespace

Json truthJson(const SynthPlan& plan, const std::string& datasetFolder)
{
    Json root;
    root["format"] = kTruthFormat;
    root["dataset"] = datasetFolder;
    root["seed"] = plan.seed;
    root["preset"] = plan.presetName;
    root["effects"] = Json::array();
    for (const auto& hidden : plan.effects)
        root["effects"].push_back(Json{{"name", hidden.effect->name}, {"parameters", parameterJson(hidden)}});
    Json sensor = Json::object();
    if (plan.dataset.sensor.highpassHz)
        sensor["highpassHz"] = *plan.dataset.sensor.highpassHz;
    if (plan.dataset.sensor.noiseRms)
        sensor["noiseRms"] = *plan.dataset.sensor.noiseRms;
    root["sensor"] = sensor;
    root["jitter"] = Json{{"force", kForceJitter}, {"motion", kMotionJitter}};
    root["trials"] = Json::array();
    for (std::size_t i = 0; i < plan.dataset.trials.size(); ++i)
        root["trials"].push_back(trialJson(plan.dataset.trials[i], plan.actual[i], plan.faults[i]));
    return root;
}

std::string describeHiddenEffects(const SynthPlan& plan)
{
    if (plan.effects.empty())
        return "none";
    std::string text;
    for (const auto& hidden : plan.effects)
        text += (text.empty() ? "" : "; ") + describeEffect(*hidden.effect, hidden.values);
    return text;
}

} // namespace rosin::discovery
