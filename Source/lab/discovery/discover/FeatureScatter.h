#pragma once
// The measurement's own scatter of each feature, the unit of every gap rosin discover reports.
//   * Repeats (several valid trials in one grid cell): the pooled within-cell standard deviation, when the
//     cells give at least 5 degrees of freedom.
//   * Otherwise neighbouring cells: second differences f[i-1] - 2 f[i] + f[i+1] of the measured feature
//     along the force axis and along the motion axis (acceleration or speed) at each beta; for independent
//     scatter sigma their standard deviation is sqrt(6) sigma, so sigma = s(d2) / sqrt(6), with s(d2) the
//     larger of 1.4826 MAD(d2) and the rms of d2 after dropping its largest 10 % (a regime boundary crossing
//     the grid is an outlier, not scatter; a heavy-tailed noise, as of a feature read at few samples, is
//     scatter that the MAD alone would miss). The feature's own curvature over the grid adds to it, so this
//     errs on the side of a larger scatter (a smaller gap).
//   * Too few triples (< 4): 1.4826 MAD of the feature over all trials (a broad upper bound).
// Every scatter is at least the feature's resolution (featureResolution).
// A category (the regime) has no difference to scale: its scatter is the share q of pairs that disagree,
// among repeats or else among adjacent cells (again an upper bound near a boundary), at least 1/9; a
// disagreement then counts z = 1 / sqrt(q), so that z^2 averages 1 when the model disagrees only as often as
// the measurement disagrees with itself (GapMeasure.h). JUCE-free.
#include <array>
#include <string>
#include <vector>

#include "lab/discovery/ScanGrid.h"
#include "lab/discovery/discover/TrialFeatures.h"

namespace rosin::discovery
{

/// The smallest mismatch rate a category is credited with: a disagreement then counts z = 3, as much as a
/// feature seen on one side only.
inline constexpr double kMinMismatchRate = 1.0 / 9.0;

struct FeatureScatter
{
    std::array<double, kFeatureCount> sigma{}; ///< in the feature's unit; for a category, its mismatch rate
    std::array<std::string, kFeatureCount> method{}; ///< "repeats", "neighbours", "spread", "resolution"
    /// Per trial (indexed like dataset.trials; empty: none), how far the model's feature moves when the
    /// trial's settings are nudged within a bowing machine's accuracy (ModelSensitivity.h); NaN where the
    /// feature appears or vanishes under the nudge.
    std::vector<std::array<double, kFeatureCount>> sensitivity{};

    /// The sigma of feature f in trial t: sqrt(sigma_f^2 + sensitivity^2), or NaN when the trial's feature
    /// is unstable under the nudge (then it is not compared).
    double trialSigma(std::size_t trial, std::size_t feature) const noexcept;
};

/// `measured` is indexed like dataset.trials.
FeatureScatter measureScatter(const ScanGrid& grid, const std::vector<TrialFeatures>& measured,
                              double sampleRate);

} // namespace rosin::discovery
