#pragma once
// Whether the measurement's residual lies along a candidate effect's own signature once what a smooth
// model-form bias could explain is taken out. Two simulators of the same physics mostly differ by a shift and
// a tilt of each feature over the grid; a missing effect leaves structure (how static friction grows with
// force, how the first slip's drop depends on it) that a shift and a tilt cannot make.
//   Per numeric feature, over the trials where the measurement, the current model and the candidate all
//   show it, in units of the trial's scatter sigma (FeatureScatter::trialSigma):
//     r = (measured - current) / sigma, the residual; g = (candidate - current) / sigma, the signature;
//   both clipped at +-kSignatureClip (a chaotic attack 20 sigma off counts as one 6 sigma off). The bias
//   allowed for is an offset and a linear trend in log beta, log force and log motion (the axes with more
//   than one value among those trials), weighted like the residual: the columns of X are (1, log beta, ...)
//   / sigma. r and g are projected on the complement of X's columns (least squares), r' and g'.
//   Over the features: z = sum g'.r' / sqrt(sum g'.g'), the matched filter's statistic, N(0, 1) for a
//   residual of unit white noise with no trace of g (and positive when the residual goes the signature's
//   way); beyondTrends = sum g'.g' / sum g.g, the share of the signature's power no offset or trend absorbs
//   (near 0: this effect cannot be told from a smooth bias on this grid, whatever its gain).
// JUCE-free.
#include <cstddef>
#include <vector>

#include "lab/discovery/ScanGrid.h"
#include "lab/discovery/discover/FeatureScatter.h"
#include "lab/discovery/discover/TrialFeatures.h"

namespace rosin::discovery
{

inline constexpr double kSignatureClip = 6.0;

struct SignatureScore
{
    double z = 0.0;            ///< matched-filter statistic (0 when the signature is all trend)
    double beyondTrends = 0.0; ///< 0..1
    std::size_t pairs = 0;     ///< trial-feature pairs compared
};

/// Over the dataset trials `trials`, which must lie on `grid`; the feature vectors are indexed like
/// dataset.trials.
SignatureScore signatureScore(const std::vector<std::size_t>& trials, const ScanGrid& grid,
                              const std::vector<TrialFeatures>& measured,
                              const std::vector<TrialFeatures>& current,
                              const std::vector<TrialFeatures>& candidate, const FeatureScatter& scatter);

} // namespace rosin::discovery
