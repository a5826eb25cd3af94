#include "lab/discovery/discover/ModelRuns.h"

#include <algorithm>
#include <map>
#include <memory>
#include <stdexcept>

#include "core/physics/laws/FrictionLawFactory.h"
#include "lab/discovery/ParallelTrials.h"
#include "lab/discovery/SensorChain.h"
#include "lab/discovery/TrialSimulator.h"

namespace rosin::discovery
{

SimulationModel baselineModel(const Dataset& dataset, const std::string& friction)
{
    const auto names = physics::frictionModelNames();
    if (std::find(names.begin(), names.end(), friction) == names.end())
    {
        std::string list;
        for (const auto& n : names)
            list += (list.empty() ? "" : ", ") + n;
        throw std::invalid_argument("--baseline: expected a friction law (" + list + ") but got \"" +
                                    friction + "\"");
    }
    SimulationModel model;
    model.preset.name = "discover-baseline";
    model.preset.string = dataset.rig.string;
    model.preset.friction = friction;
    const std::string body = dataset.rig.body.value_or("cello");
    if (body != "cello" && body != "violin" && body != "rigid")
        throw DatasetError(dataset.descriptionPath(), "rig.body",
                           "\"cello\", \"violin\" or \"rigid\" (rosin discover simulates no other body)",
                           "\"" + body + "\"");
    model.preset.body = body;
    return model;
}

namespace
{
Gesture nudged(Gesture gesture, double factor)
{
    if (auto* a = std::get_if<ConstantAcceleration>(&gesture))
        a->acceleration *= factor;
    else if (auto* v = std::get_if<Steady>(&gesture))
        v->speed *= factor;
    return gesture;
}

// The simulated channel the dataset also records, or nullptr.
const std::vector<double>* recorded(const std::vector<Channel>& layout,
                                    const std::vector<std::vector<double>>& channels, const std::string& name)
{
    for (std::size_t c = 0; c < layout.size(); ++c)
        if (layout[c].name == name)
            return &channels[c];
    return nullptr;
}

// Trial i of `dataset` simulated with `sim`: the recorded channels through the dataset's stated sensor.
StringRun runString(TrialSimulator& sim, const Dataset& dataset, std::size_t i, double seconds,
                    SettingsNudge nudge)
{
    const Trial& trial = dataset.trials[i];
    TrialSettings s;
    s.beta = trial.beta;
    s.bowForce = trial.bowForce * nudge.bowForce;
    s.gesture = nudged(trial.gesture, nudge.motion);
    s.seconds = seconds;
    const auto& samples = sim.run(s);
    StringRun run;
    for (const auto& channel : dataset.channels)
        if (channel.name != "bowForceMeasured")
        {
            run.layout.push_back(channel);
            run.channels.push_back(channelSamples(samples, channel.name));
        }
    applySensorResponse(run.layout, run.channels, dataset.sensor, static_cast<double>(dataset.sampleRate));
    return run;
}

// The calibrated chain (gain, low-pass, the force channels' lag) applied to a copy of `run`, then analysed
// like a measurement.
TrialFeatures measuredFeatures(StringRun run, const NuisanceValues& nuisance, const Dataset& dataset,
                               const Trial& trial)
{
    auto& [layout, channels] = run;
    const double fs = static_cast<double>(dataset.sampleRate);
    applyGaugeCalibration(layout, channels, nuisance.sensorGain, sensorLowpassHz(nuisance, fs), fs);
    // Force channels that lag the gesture (and its recorded velocity): shifted, length kept.
    if (const std::size_t d = sensorDelaySamples(nuisance, fs); d > 0)
        for (std::size_t c = 0; c < layout.size(); ++c)
            if (layout[c].name == "bridgeForce" || layout[c].name == "frictionForce")
            {
                auto& ch = channels[c];
                const std::size_t n = ch.size();
                ch.insert(ch.begin(), d, 0.0);
                ch.resize(n);
            }
    return computeTrialFeatures(*recorded(layout, channels, "bridgeForce"), featureContext(dataset, trial),
                                {recorded(layout, channels, "bowPointVelocity"),
                                 recorded(layout, channels, "frictionForce"),
                                 recorded(layout, channels, "bowVelocity")});
}
} // namespace

std::size_t StringRun::bytes() const noexcept
{
    std::size_t n = 0;
    for (const auto& c : channels)
        n += c.size() * sizeof(double);
    return n;
}

std::vector<TrialFeatures> simulateFeatures(const SimulationModel& model, const Dataset& dataset,
                                            const std::vector<std::size_t>& trials,
                                            const std::vector<double>& seconds, unsigned threads,
                                            SettingsNudge nudge, StringRuns* runs)
{
    std::vector<TrialFeatures> out(dataset.trials.size());
    if (runs)
        runs->resize(dataset.trials.size()); // each worker fills only its own trial's slot
    auto makeWorker = [&model, &dataset, &seconds, nudge, runs]() -> std::function<TrialFeatures(std::size_t)>
    {
        // One simulator per ambient temperature (usually one): preparing a thermal law calibrates it.
        auto simulators = std::make_shared<std::map<double, std::unique_ptr<TrialSimulator>>>();
        return [simulators, &model, &dataset, &seconds, nudge, runs](std::size_t i)
        {
            const Trial& trial = dataset.trials[i];
            if (runs && !(*runs)[i].channels.empty())
                return measuredFeatures((*runs)[i], model.nuisance, dataset, trial);
            const double ambient = dataset.ambientTemperature(trial).value_or(kCalibrationAmbient);
            auto& sim = (*simulators)[ambient];
            if (!sim)
            {
                SimulationModel m = model;
                m.preset.ambientOffset += ambient - kCalibrationAmbient;
                sim = std::make_unique<TrialSimulator>(m, static_cast<double>(dataset.sampleRate));
            }
            StringRun run = runString(*sim, dataset, i, seconds[i], nudge);
            if (runs)
                (*runs)[i] = run;
            return measuredFeatures(std::move(run), model.nuisance, dataset, trial);
        };
    };
    runParallel<TrialFeatures>(trials, threads, makeWorker,
                               [&out](std::size_t i, TrialFeatures&& f) { out[i] = f; });
    return out;
}

} // namespace rosin::discovery
