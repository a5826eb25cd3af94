#pragma once
// The gap between measured and simulated features, in units of the measurement's scatter.
//   z = (measured - simulated) / sigma per trial and feature; a feature that one side shows and the other
//   does not (a slip in one, none in the other) counts as z = +-3 (kMissingZ).
//   Per feature: the excess rms  gap = sqrt(max(0, mean(z^2) - 1)) over the trials where either side has
//   the feature: 0 means the model agrees within the measurement's scatter, 1 that the disagreement is as
//   large again as the scatter. Overall gap: the mean over features present in at least 3 trials.
//   A trial's error (for the paired test): the mean z^2 over its features.
// JUCE-free.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "FeatureScatter.h"
#include "TrialFeatures.h"
#include "discovery/Dataset.h"
#include "discovery/ScanGrid.h"

namespace rosin::discovery
{

inline constexpr double kMissingZ = 3.0;
inline constexpr std::size_t kMinTrialsForGap = 3;

std::optional<double> normalisedDifference(const std::optional<double>& measured,
                                           const std::optional<double>& simulated, double sigma);

struct GapSummary
{
    std::array<double, kFeatureCount> meanSquare{}; ///< mean z^2 per feature (0 when no trial)
    std::array<std::size_t, kFeatureCount> count{}; ///< trials with the feature on either side
    std::array<double, kFeatureCount> gap{};        ///< excess rms per feature
    double overall = 0.0;
    /// Mean over features (with >= kMinTrialsForGap trials) of mean z^2: the quantity a fit minimises.
    double objective = 0.0;
};

/// Over the dataset trials `trials`; the feature vectors are indexed like dataset.trials.
GapSummary measureGap(const std::vector<std::size_t>& trials, const std::vector<TrialFeatures>& measured,
                      const std::vector<TrialFeatures>& simulated, const FeatureScatter& scatter);

/// The trial's mean z^2 over its features, or nullopt if neither side has any.
std::optional<double> trialError(const TrialFeatures& measured, const TrialFeatures& simulated,
                                 const FeatureScatter& scatter);

/// Where on the grid a feature's z^2 is largest: each axis with more than one value split at its middle,
/// the region (of 2 to 8) with the largest mean z^2, as text ("force 0.4-1.5 N, acceleration 0.08-1.1
/// m/s^2, beta 0.0899: measured above the model by 4.2 sigma on average (9 trials)"); "" if no trial.
std::string whereLargest(std::size_t feature, const Dataset& dataset, const ScanGrid& grid,
                         const std::vector<std::size_t>& trials, const std::vector<TrialFeatures>& measured,
                         const std::vector<TrialFeatures>& simulated, const FeatureScatter& scatter);

} // namespace rosin::discovery
