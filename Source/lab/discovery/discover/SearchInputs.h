#pragma once
// What every fit of rosin discover works from: the dataset, its grid, the training / held-out split, the
// measured features and their scatter. JUCE-free.
#include <cstdint>
#include <ostream>
#include <vector>

#include "lab/discovery/Dataset.h"
#include "lab/discovery/ScanGrid.h"
#include "lab/discovery/discover/FeatureScatter.h"
#include "lab/discovery/discover/TrialFeatures.h"

namespace rosin::discovery
{

/// The search adopts at most this many effects.
inline constexpr std::size_t kMaxEffects = 3;

struct SearchInputs
{
    const Dataset* dataset = nullptr;
    const ScanGrid* grid = nullptr;
    std::vector<std::size_t> training, heldOut; ///< dataset trial indices
    std::vector<TrialFeatures> measured;        ///< indexed like dataset.trials
    FeatureScatter scatter;
    std::vector<double> seconds; ///< each trial's length, s
    unsigned threads = 1;
    std::uint64_t seed = 0;
    std::size_t maxEffects = kMaxEffects; ///< 1 to kMaxEffects: a quicker answer that stops after fewer
    std::ostream* log = nullptr;          ///< progress lines, or nullptr
    /// The model a fit's candidates are compared with, its features indexed like dataset.trials (the
    /// baseline for the calibration, the current model in the effect search): a candidate that stops
    /// showing Helmholtz motion where that model shows it gains nothing there (GapMeasure.h).
    std::vector<TrialFeatures> reference;
};

} // namespace rosin::discovery
