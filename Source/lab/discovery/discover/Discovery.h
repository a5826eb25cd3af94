#pragma once
// rosin discover's engine, JUCE-free: from a dataset and the features of its measured
// trials, the baseline's gap per feature, the effect search, and the gap after. The command reads the
// trial files (discovery/io) and writes the outputs (DiscoveryReport.h).
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "lab/discovery/Dataset.h"
#include "lab/discovery/ScanGrid.h"
#include "lab/discovery/discover/Calibration.h"
#include "lab/discovery/discover/EffectSearch.h"
#include "lab/discovery/discover/FeatureScatter.h"
#include "lab/discovery/discover/GapMeasure.h"
#include "lab/discovery/discover/TrialFeatures.h"

namespace rosin::discovery
{

struct DiscoverySettings
{
    std::string baseline = "plastic";
    unsigned threads = 1;
    std::uint64_t seed = 0;
    std::size_t maxEffects = kMaxEffects; ///< the search stops after adopting this many (1 to kMaxEffects)
    std::ostream* log = nullptr;
};

struct Discovery
{
    std::string datasetFolder;
    std::string baselineFriction;
    ScanGrid grid;
    std::size_t trialsUsed = 0, trialsSkipped = 0;
    std::size_t maxEffects = kMaxEffects; ///< as asked (DiscoverySettings)
    std::vector<std::size_t> used;        ///< dataset indices of the trials used
    std::vector<std::size_t> training, heldOut;
    FeatureScatter scatter;
    /// Indexed like dataset.trials: measured; the nominal baseline's; the calibrated baseline's; the final
    /// model's (calibrated baseline + adopted effects, the calibration refitted with them).
    std::vector<TrialFeatures> measured, baseline, calibrated, final;
    CalibrationResult calibration;
    NuisanceValues finalNuisance; ///< as refitted together with the adopted effects
    /// Over all used trials: the nominal baseline (gapBefore), calibrated, the final model (gapAfter).
    GapSummary gapBefore, gapCalibrated, gapAfter;
    /// The same three in units of the scatter widened by the model-form tolerance (ModelFormTolerance.h),
    /// the verdict's units: the part of the gap that two string models with the same physics do not
    /// already leave between them. Reported beside the gaps; no fit or test uses it.
    GapSummary beyondToleranceBefore, beyondToleranceCalibrated, beyondToleranceAfter;
    std::array<std::string, kFeatureCount> whereBefore, whereAfter;
    SearchResult search;
    std::vector<GapSummary> stepGaps; ///< over all used trials after each adopted effect
    GapSignificance remaining;        ///< of the gap left after the adopted effects (gapAfter)
    /// "effect-found" (an effect adopted), "unexplained" (none adopted, yet the calibrated baseline's gap is
    /// significant: p < kSignificanceLevel) or "no-significant-discrepancy" (the calibration within the
    /// lab's tolerances explains the data).
    std::string status;
    double seconds = 0.0;
};

/// `measured[i]` are the features of dataset trial i (valid trials only are read), `seconds[i]` its length.
Discovery runDiscovery(const Dataset& dataset, std::vector<TrialFeatures> measured,
                       std::vector<double> seconds, const DiscoverySettings& settings);

} // namespace rosin::discovery
