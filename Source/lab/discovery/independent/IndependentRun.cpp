#include "lab/discovery/independent/IndependentRun.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "lab/discovery/independent/IndependentStreams.h"
#include "lab/discovery/independent/IndependentTrial.h"

namespace rosin::discovery
{

namespace
{
const std::vector<double>& traceChannel(const TrialTrace& t, const std::string& name)
{
    if (name == "bridgeForce")
        return t.bridgeForce;
    if (name == "frictionForce")
        return t.frictionForce;
    if (name == "bowPointVelocity")
        return t.bowPointVelocity;
    if (name == "bowVelocity")
        return t.bowVelocity;
    throw std::invalid_argument("independent generator: no channel \"" + name + "\"");
}

std::function<CleanTrial(std::size_t)> makeWorker(const SynthPlan& plan, const IndependentTruth& truth)
{
    const double fs = plan.dataset.sampleRate;
    const IndependentRig rig = rigFromPlan(plan, truth.nuisance, truth.effects, truth.member);
    auto sim = std::make_shared<IndependentTrialSimulator>(rig, truth.member.oversampling * fs);
    return [sim, &plan, &truth, fs](std::size_t i)
    {
        const TrialSettings& actual = plan.actual[i];
        const TrialTrace& trace = sim->run(actual);
        const auto samples = static_cast<std::size_t>(std::llround(actual.seconds * fs));
        CleanTrial t;
        for (std::size_t c = 0; c < plan.dataset.channels.size(); ++c)
        {
            const std::string& name = plan.dataset.channels[c].name;
            std::vector<double> x = name == "bowForceMeasured"
                                        ? std::vector<double>(trace.bowVelocity.size(), actual.bowForce)
                                        : traceChannel(trace, name);
            x = acquire(x, sim->internalRate(), truth.startDelays[i], truth.chain.cornerHz,
                        truth.chain.gains[c], truth.member.oversampling, truth.member.antiAliasOrder);
            x.resize(samples, x.empty() ? 0.0 : x.back());
            if (name == "bridgeForce")
                for (double v : x)
                    t.peakBridgeForce = std::max(t.peakBridgeForce, std::abs(v));
            t.channels.push_back(std::move(x));
        }
        return t;
    };
}

void measure(const SynthPlan& plan, std::size_t i, std::vector<std::vector<double>>& channels)
{
    const Dataset& d = plan.dataset;
    for (std::size_t c = 0; c < channels.size(); ++c)
        if (d.sensor.highpassHz && *d.sensor.highpassHz > 0.0 && d.channels[c].unit == "N")
            firstOrderHighPassBilinear(channels[c], *d.sensor.highpassHz, d.sampleRate);
    SeededRandom noise(plan.seed, independent_streams::kNoise, i);
    const double rms = d.sensor.noiseRms.value_or(0.0);
    for (auto& channel : channels)
        for (double& v : channel)
            v += rms * noise.normal();
    if (plan.faults[i])
        applyTrialFault(*plan.faults[i], d.sampleRate, channels);
}

nlohmann::ordered_json object(const std::vector<std::pair<std::string, double>>& values)
{
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (const auto& [k, v] : values)
        j[k] = v;
    return j;
}
} // namespace

IndependentTruth independentTruth(const SynthPlan& plan)
{
    IndependentTruth t;
    t.seed = plan.seed;
    t.member = generatorMember(plan.generatorMember);
    t.nuisance = drawNuisance(plan.seed);
    t.effects = drawOwnEffects(plan);
    t.channels = plan.dataset.channels;
    t.chain = drawChain(plan.seed, plan.dataset.channels.size(), plan.dataset.sampleRate);
    for (std::size_t i = 0; i < plan.dataset.trials.size(); ++i)
        t.startDelays.push_back(drawStartDelay(plan.seed, i));
    return t;
}

std::vector<std::pair<std::string, double>> IndependentTruth::values() const
{
    std::vector<std::pair<std::string, double>> v{{"generator.oversampling", member.oversampling}};
    if (member.number != 0)
        for (const auto& [k, x] : member.values())
            v.push_back({"generator." + k, x});
    for (const auto& [k, x] : nuisance.values())
        v.push_back({"nuisance." + k, x});
    for (const auto& [k, x] : effects.values())
        v.push_back({"effect." + k, x});
    for (const auto& [k, x] : chain.values(channels))
        v.push_back({"chain." + k, x});
    return v;
}

nlohmann::ordered_json IndependentTruth::toJson() const
{
    nlohmann::ordered_json j;
    j["generator"] = kIndependentGenerator;
    j["seed"] = seed;
    j["oversampling"] = member.oversampling;
    if (member.number != 0)
        j["member"] = object(member.values());
    j["nuisance"] = object(nuisance.values());
    j["effects"] = object(effects.values());
    j["chain"] = object(chain.values(channels));
    j["startDelays"] = startDelays;
    return j;
}

void runIndependentSynthData(SynthPlan& plan, unsigned threads, const MeasuredTrialSink& sink)
{
    const IndependentTruth truth = independentTruth(plan);
    (void)rigFromPlan(plan, truth.nuisance, truth.effects, truth.member); // throws before any thread starts
    const SynthPlan& constPlan = plan;
    runPilotFirst(
        plan, threads, [&constPlan, &truth] { return makeWorker(constPlan, truth); },
        [&constPlan](std::size_t i, std::vector<std::vector<double>>& channels)
        { measure(constPlan, i, channels); },
        sink);
}

} // namespace rosin::discovery
