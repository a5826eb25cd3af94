#include "lab/discovery/discover/Discovery.h"

#include <algorithm>
#include <chrono>

#include "lab/discovery/discover/ModelFormTolerance.h"
#include "lab/discovery/discover/ModelRuns.h"
#include "lab/discovery/discover/ModelSensitivity.h"

namespace rosin::discovery
{

Discovery runDiscovery(const Dataset& dataset, std::vector<TrialFeatures> measured,
                       std::vector<double> seconds, const DiscoverySettings& settings)
{
    const auto start = std::chrono::steady_clock::now();
    Discovery d;
    d.datasetFolder = dataset.folder;
    d.baselineFriction = settings.baseline;
    d.grid = findScanGrid(dataset);
    for (const auto& cell : d.grid.cells)
        d.used.insert(d.used.end(), cell.trials.begin(), cell.trials.end());
    std::sort(d.used.begin(), d.used.end());
    d.trialsUsed = d.used.size();
    d.trialsSkipped = dataset.trials.size() - d.used.size();
    d.measured = std::move(measured);
    d.scatter = measureScatter(d.grid, d.measured, dataset.sampleRate);
    splitTrials(d.grid, d.training, d.heldOut);

    const SimulationModel base = baselineModel(dataset, settings.baseline);
    d.baseline = simulateFeatures(base, dataset, d.used, seconds, settings.threads);
    addModelSensitivity(d.scatter, base, dataset, d.used, d.baseline, seconds, settings.threads);
    d.gapBefore = measureGap(d.used, d.measured, d.baseline, d.scatter);
    for (std::size_t f = 0; f < kFeatureCount; ++f)
        d.whereBefore[f] = whereLargest(f, dataset, d.grid, d.used, d.measured, d.baseline, d.scatter);
    if (settings.log)
        *settings.log << "baseline (" << settings.baseline << "): gap " << d.gapBefore.overall << "\n"
                      << std::flush;

    SearchInputs in;
    in.dataset = &dataset;
    in.grid = &d.grid;
    in.training = d.training;
    in.heldOut = d.heldOut;
    in.measured = d.measured;
    in.scatter = d.scatter;
    in.seconds = seconds;
    in.threads = settings.threads;
    in.seed = settings.seed;
    in.maxEffects = settings.maxEffects;
    d.maxEffects = settings.maxEffects;
    in.log = settings.log;
    in.reference = d.baseline;
    d.calibration = calibrate(in, base);
    SimulationModel calibrated = base;
    calibrated.nuisance = d.calibration.values;
    d.calibrated = simulateFeatures(calibrated, dataset, d.used, seconds, settings.threads);
    d.gapCalibrated = measureGap(d.used, d.measured, d.calibrated, d.scatter);
    if (settings.log)
        *settings.log << "calibrated baseline: gap " << d.gapCalibrated.overall << "\n" << std::flush;
    d.search = searchEffects(in, calibrated, base.nuisance, d.calibration.active);

    d.final = d.calibrated;
    for (const auto& step : d.search.steps)
    {
        d.final = simulateFeatures(step.model, dataset, d.used, seconds, settings.threads);
        d.stepGaps.push_back(measureGap(d.used, d.measured, d.final, d.scatter));
    }
    d.finalNuisance = d.search.model.nuisance;
    d.gapAfter = measureGap(d.used, d.measured, d.final, d.scatter);
    for (std::size_t f = 0; f < kFeatureCount; ++f)
        d.whereAfter[f] = whereLargest(f, dataset, d.grid, d.used, d.measured, d.final, d.scatter);
    const FeatureScatter widened = withModelFormTolerance(d.scatter);
    d.beyondToleranceBefore = measureGap(d.used, d.measured, d.baseline, widened);
    d.beyondToleranceCalibrated = measureGap(d.used, d.measured, d.calibrated, widened);
    d.beyondToleranceAfter = measureGap(d.used, d.measured, d.final, widened);
    d.remaining = gapSignificance(d.beyondToleranceAfter);
    d.status = !d.search.steps.empty()                   ? "effect-found"
               : d.remaining.pValue < kSignificanceLevel ? "unexplained"
                                                         : "no-significant-discrepancy";
    d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return d;
}

} // namespace rosin::discovery
