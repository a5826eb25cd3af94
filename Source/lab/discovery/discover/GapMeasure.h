#pragma once
// The gap between measured and simulated features, in units of the measurement's scatter.
//   z = (measured - simulated) / sigma per trial and feature (FeatureScatter::trialSigma: the measurement's
//   scatter and the model's sensitivity to the trial's settings); a feature that one side shows and the
//   other does not (a slip in one, none in the other) counts as z = +-3 (kMissingZ). Features that describe
//   established Helmholtz motion (pitch, harmonic tilt) have two trial sets (HelmholtzTrials):
//   * BothSides, for the gaps reported and the verdict: compared only where both sides show the motion.
//     Whether it was reached is the transient's and the regime's evidence; counting it again would weigh a
//     chaotic boundary twice (measured: on an independent model's data with nothing hidden, 12 Guettler
//     trials reach Helmholtz motion in 0.4 s where the calibrated model does not, within the regime's own
//     scatter, and at z = 3 they alone would make the pitch's gap "significant", p 1e-17).
//   * MeasuredSide, for every fit and the paired test: compared where the measurement shows the motion, a
//     model that misses it there at z = 3. The measured side fixes the trials, so a candidate cannot leave
//     the comparison of a feature it gets wrong by stopping the model's motion (seen with BothSides: an
//     effect that stopped it where its pitch was 10 sigma off lowered the objective while the gap grew
//     1.45 -> 2.32). Baseline and candidate pay alike for the trials both miss. A trial that the candidate
//     misses while the model it is compared with (`reference`) is more than 3 sigma off there scores that
//     model's loss: losing the motion gains nothing on a feature, however wrong the feature was.
//   A category (the regime) compares as same (z = 0) or different (z = 1 / sqrt(q),
//   q its mismatch rate, at most 3).
//   Noise model: Student-t with kStudentNu = 4 degrees of freedom, i.e. a trial's loss is
//   rho(z) = nu ln(1 + z^2 / nu) (its negative log-likelihood up to a constant, scaled so rho ~ z^2 for
//   small z). It grows without bound, so shrinking a 6-sigma misfit to 1 sigma counts (9.2 -> 0.9), but
//   only logarithmically, so one chaotic attack 20 sigma off (a transient of 14 periods against 5, where 1 %
//   more force changes the outcome) weighs like three trials 2 sigma off, not like a hundred. (The loss it
//   replaces clipped z at 3: a large improvement and a small one scored alike.)
//   Per feature: gap = sqrt(max(0, mean rho - E[rho])), E[rho] its mean for a right model (z ~ N(0, 1)):
//   0 means the model agrees within the measurement's scatter, 1 that the excess loss is one sigma^2.
//   Overall gap: the mean over features present in at least 3 trials.
//   A trial's error (for the paired test): its share of the objective (objectiveShares).
// JUCE-free.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "lab/discovery/Dataset.h"
#include "lab/discovery/ScanGrid.h"
#include "lab/discovery/discover/FeatureScatter.h"
#include "lab/discovery/discover/TrialFeatures.h"

namespace rosin::discovery
{

inline constexpr double kMissingZ = 3.0;
inline constexpr double kStudentNu = 4.0;

/// Which trials a Helmholtz-motion feature is compared in (see above).
enum class HelmholtzTrials
{
    BothSides,
    MeasuredSide
};

/// rho(z) = nu ln(1 + z^2 / nu), the Student-t loss of one normalised difference.
double robustLoss(double z) noexcept;
/// E[rho(z)] for z ~ N(0, 1), by quadrature (0.775 for nu = 4): the loss of a model that is right.
double nullLoss() noexcept;
inline constexpr std::size_t kMinTrialsForGap = 3;

/// z of one feature of one trial, or nullopt when it is not compared (absent on both sides, a property of
/// Helmholtz motion (see describesHelmholtzMotion) absent on a side `trials` does not compare, or sigma NaN:
/// unstable in the model).
std::optional<double> normalisedDifference(std::size_t feature, const std::optional<double>& measured,
                                           const std::optional<double>& simulated, double sigma,
                                           HelmholtzTrials trials = HelmholtzTrials::BothSides);

struct GapSummary
{
    /// mean min(z^2, 9) per feature (0 when no trial): the chi-square test's statistic (gapSignificance)
    std::array<double, kFeatureCount> meanSquare{};
    std::array<double, kFeatureCount> meanLoss{};   ///< mean rho(z) per feature
    std::array<std::size_t, kFeatureCount> count{}; ///< trials with the feature on either side
    std::array<double, kFeatureCount> gap{};        ///< excess rms per feature
    double overall = 0.0;
    /// Mean over features (with >= kMinTrialsForGap trials) of mean rho(z): the quantity a fit minimises.
    double objective = 0.0;
};

/// Over the dataset trials `trials`; the feature vectors are indexed like dataset.trials.
/// `reference` (MeasuredSide only; empty: none), indexed like dataset.trials: the model `simulated` is
/// compared with, for the rule above.
GapSummary measureGap(const std::vector<std::size_t>& trials, const std::vector<TrialFeatures>& measured,
                      const std::vector<TrialFeatures>& simulated, const FeatureScatter& scatter,
                      HelmholtzTrials helmholtz = HelmholtzTrials::BothSides,
                      const std::vector<TrialFeatures>& reference = {});
/// The gap a fit minimises and the paired test compares (HelmholtzTrials::MeasuredSide).
inline GapSummary fitGap(const std::vector<std::size_t>& trials, const std::vector<TrialFeatures>& measured,
                         const std::vector<TrialFeatures>& simulated, const FeatureScatter& scatter,
                         const std::vector<TrialFeatures>& reference = {})
{
    return measureGap(trials, measured, simulated, scatter, HelmholtzTrials::MeasuredSide, reference);
}

/// Each trial's share of fitGap's objective over `trials` (same order; they sum to the objective): its
/// rho(z) of every counted feature divided by that feature's trial count and by the number of features. The
/// paired test compares these, so a feature seen in few trials (the tilt of established Helmholtz motion)
/// weighs as much in the test as in the gap, not as little as its trials are few.
std::vector<double> objectiveShares(const std::vector<std::size_t>& trials,
                                    const std::vector<TrialFeatures>& measured,
                                    const std::vector<TrialFeatures>& simulated,
                                    const FeatureScatter& scatter,
                                    const std::vector<TrialFeatures>& reference = {});

/// Whether a gap is more than the measurement's scatter explains: per feature with at least
/// kMinTrialsForGap trials, sum min(z^2, 9) over its n trials against chi-square with n degrees of freedom
/// (z is N(0, 1) when the model is right; the clip at 3 only lowers the sum, so the test errs towards
/// "within the scatter" where a few trials are wildly off), upper tail by the Wilson-Hilferty
/// cube-root approximation; the smallest p, Bonferroni-corrected over the features tested.
struct GapSignificance
{
    double pValue = 1.0;
    std::size_t feature = kFeatureCount; ///< the feature that gave the smallest p (kFeatureCount: none)
};
GapSignificance gapSignificance(const GapSummary& gap);

/// Where on the grid a feature's loss rho(z) is largest: each axis with more than one value split at its
/// middle, the region (of 2 to 8) with the largest mean rho, as text ("force 0.4-1.5 N, acceleration 0.08-1.1
/// m/s^2, beta 0.0899: measured above the model by 4.2 sigma on average (9 trials)"); "" if no trial.
std::string whereLargest(std::size_t feature, const Dataset& dataset, const ScanGrid& grid,
                         const std::vector<std::size_t>& trials, const std::vector<TrialFeatures>& measured,
                         const std::vector<TrialFeatures>& simulated, const FeatureScatter& scatter);

} // namespace rosin::discovery
