#pragma once
// Runs a SynthPlan: every trial simulated with the hidden model at its actual (jittered) settings on all
// threads, then measured as the laboratory would measure it (SensorChain: the force gauges' high-pass, the
// noise floor; then the trial's fault, if it failed), and handed on in trial order.
//
// The noise floor is a property of the sensor, one number for the dataset: about 0.3 % of
// the typical peak bridge force, as the workflow's specification asks. It is set from a pilot of up to 8
// trials spread over the grid (computed first), as a laboratory sets its gain from a few test strokes; the
// median of their peak |bridge force| times kNoiseShareOfPeak, rounded to 2 significant digits, becomes
// sensor.noiseRms. Only the pilot and the few trials that finish out of order are held in memory, so a large
// scan needs no more than a small one.
#include <cstddef>
#include <functional>
#include <vector>

#include "lab/discovery/synth/SynthPlan.h"

namespace rosin::discovery
{

/// Receives trial `index` of plan.dataset.trials with its measured channels (dataset channel order).
using MeasuredTrialSink =
    std::function<void(std::size_t index, const std::vector<std::vector<double>>& channels)>;

/// A trial as simulated, before the measurement chain's high-pass, noise and fault.
struct CleanTrial
{
    std::vector<std::vector<double>> channels; ///< dataset channel order
    double peakBridgeForce = 0.0;              ///< N, max |bridgeForce|
};

/// Turns a clean trial into a measured one in place (high-pass, noise, fault), on the calling thread.
using TrialMeasurement = std::function<void(std::size_t index, std::vector<std::vector<double>>& channels)>;

/// The schedule both generators share: the pilot's trials first, the noise floor from their peaks
/// (noiseFromPeaks, unless already set), then every trial measured and handed to `sink` in trial order.
/// `makeWorker` is called once per thread and returns that thread's simulator.
void runPilotFirst(SynthPlan& plan, unsigned threads,
                   const std::function<std::function<CleanTrial(std::size_t)>()>& makeWorker,
                   const TrialMeasurement& measure, const MeasuredTrialSink& sink);

/// Sets plan.dataset.sensor.noiseRms (before the first sink call) and calls `sink` once per trial, in trial
/// order, on the calling thread. threads = 0: every core.
void runSynthData(SynthPlan& plan, unsigned threads, const MeasuredTrialSink& sink);

/// The pilot's trials: up to 8, evenly spread over `trials` (ascending).
std::vector<std::size_t> pilotTrials(std::size_t trials);
/// sensor.noiseRms from the pilot's peak bridge forces (N): kNoiseShareOfPeak x their median, 2 digits.
double noiseFromPeaks(std::vector<double> peaks);

} // namespace rosin::discovery
