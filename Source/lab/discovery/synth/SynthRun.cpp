#include "lab/discovery/synth/SynthRun.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <thread>

#include "lab/discovery/ParallelTrials.h"
#include "lab/discovery/SensorChain.h"

namespace rosin::discovery
{

namespace
{
constexpr std::size_t kPilotTrials = 8;

std::function<CleanTrial(std::size_t)> makeWorker(const SynthPlan& plan)
{
    auto simulator =
        std::make_shared<TrialSimulator>(plan.model, static_cast<double>(plan.dataset.sampleRate));
    return [simulator, &plan](std::size_t i)
    {
        const auto& samples = simulator->run(plan.actual[i]);
        CleanTrial t;
        for (const auto& c : plan.dataset.channels)
            t.channels.push_back(channelSamples(samples, c.name));
        for (const auto& s : samples)
            t.peakBridgeForce = std::max(t.peakBridgeForce, std::abs(s.bridgeForce));
        return t;
    };
}

void measure(const SynthPlan& plan, std::size_t i, std::vector<std::vector<double>>& channels)
{
    const Dataset& d = plan.dataset;
    applySensorResponse(d.channels, channels, d.sensor, d.sampleRate);
    SeededRandom noise(plan.seed, RandomStream::Noise, i);
    addSensorNoise(channels, d.sensor, noise);
    if (plan.faults[i])
        applyTrialFault(*plan.faults[i], d.sampleRate, channels);
}
} // namespace

std::vector<std::size_t> pilotTrials(std::size_t trials)
{
    const std::size_t count = std::min(kPilotTrials, trials);
    std::vector<std::size_t> pilot;
    for (std::size_t k = 0; k < count; ++k)
        pilot.push_back((2 * k + 1) * trials / (2 * count));
    return pilot;
}

double noiseFromPeaks(std::vector<double> peaks)
{
    if (peaks.empty())
        return 1e-6;
    std::sort(peaks.begin(), peaks.end());
    const std::size_t n = peaks.size();
    const double median = n % 2 ? peaks[n / 2] : 0.5 * (peaks[n / 2 - 1] + peaks[n / 2]);
    const double rms = kNoiseShareOfPeak * median;
    if (!(rms > 0.0) || !std::isfinite(rms))
        return 1e-6; // a silent pilot: a floor still exists
    const double scale = std::pow(10.0, 1 - static_cast<int>(std::floor(std::log10(rms))));
    return std::round(rms * scale) / scale;
}

void runPilotFirst(SynthPlan& plan, unsigned threads,
                   const std::function<std::function<CleanTrial(std::size_t)>()>& makeWorker,
                   const TrialMeasurement& measure, const MeasuredTrialSink& sink)
{
    const std::size_t n = plan.dataset.trials.size();
    const std::vector<std::size_t> pilot = pilotTrials(n);
    std::vector<std::size_t> jobs = pilot;
    for (std::size_t i = 0; i < n; ++i)
        if (!std::binary_search(pilot.begin(), pilot.end(), i))
            jobs.push_back(i);

    std::map<std::size_t, CleanTrial> waiting;
    std::vector<double> pilotPeaks;
    std::size_t nextToWrite = 0;
    auto take = [&](std::size_t i, CleanTrial&& trial)
    {
        if (std::binary_search(pilot.begin(), pilot.end(), i))
            pilotPeaks.push_back(trial.peakBridgeForce);
        waiting.emplace(i, std::move(trial));
        if (pilotPeaks.size() < pilot.size())
            return;
        if (!plan.dataset.sensor.noiseRms)
            plan.dataset.sensor.noiseRms = noiseFromPeaks(pilotPeaks);
        for (auto it = waiting.find(nextToWrite); it != waiting.end(); it = waiting.find(nextToWrite))
        {
            measure(nextToWrite, it->second.channels);
            sink(nextToWrite, it->second.channels);
            waiting.erase(it);
            ++nextToWrite;
        }
    };
    const unsigned count = threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
    runParallel<CleanTrial>(jobs, count, makeWorker, take);
}

void runSynthData(SynthPlan& plan, unsigned threads, const MeasuredTrialSink& sink)
{
    const SynthPlan& constPlan = plan;
    runPilotFirst(
        plan, threads, [&constPlan] { return makeWorker(constPlan); },
        [&constPlan](std::size_t i, std::vector<std::vector<double>>& channels)
        { measure(constPlan, i, channels); },
        sink);
}

} // namespace rosin::discovery
