#pragma once
// The effect search of rosin discover: every effect of the EffectCatalog is fitted on a
// training half of the trials, on top of the calibrated baseline (Calibration.h), and scored on the other
// half; the best significant one is adopted, and the search repeats on what remains (at most three).
//   Split: a checkerboard over the grid, (beta + force + motion index) even -> training, odd -> held out
//          (repeats of a cell stay together), so both halves cover the whole scan.
//   Fit:   a grid over the catalog's fit range (7 points for one parameter, 5 x 5 for two, 4 x 4 for two
//          beside a choice; log-spaced where the catalog says so; every choice), then, where the grid's best
//          lowers the training objective by 2 %, a golden-section refinement of each continuous parameter
//          around the best point (5 evaluations each), from the
//          nuisance values as stated (nominal, but for the tuning and the measurement chain; after an adopted
//          effect, those fitted with it): a calibration may already have bent them to mimic the effect.
//          Then, if the effect lowered the training objective by 2 %, the calibration's active nuisance
//          parameters are fitted again with the effect in place (3 each, over their prior) and the effect's
//          parameters refined once more (3 each), and if that moved the nuisance, both once more over half
//          the width (the two trade off along a ridge: a larger contact against less creep); values are
//          rounded to 3 significant digits. The objective is the training trials' Student-t loss averaged
//          over features (GapSummary::objective). Each evaluation simulates the training trials. Why held-out
//          likelihood and not an information criterion: an effect's parameters are few but its fit is a
//          search over a nonlinear, partly chaotic model, where parameter counting (AIC, BIC) says little
//          about how much it can overfit; scoring on trials the fit never saw penalises exactly the
//          flexibility the effect has, extra parameters included.
//   Score: against the current model (the calibrated baseline and the effects adopted so far):
//          held-out gain = 1 - sum e_i(with effect) / sum e_i(current model) over the held-out trials,
//          e_i a trial's share of the objective (objectiveShares), so the gain is the held-out objective's
//          relative fall. Significant when the paired sign-flip test gives p < alpha / 2, alpha = 0.01 /
//          (effects tried) (Bonferroni over the candidates), AND the gain is at least 20 %.
//   Null:  a candidate whose fit ends at its null (no growth, no margin, no extra loss, ...) explains
//          nothing of its own: whatever its held-out gain (the nuisance refit's), it is not significant, and
//          the log, the report and the JSON (leftNull) say that its fit never left the null.
//   Cross-fit: a candidate that comes close on the held-out half (p < 0.05 and a gain of at least 10 %,
//          yet not significant) is also fitted on the held-out half and scored on the training half, and
//          the test and the gain are taken over every trial of both: significant when p < alpha / 2 and the
//          gain is at least 20 %. Why: half of a scan's trials can leave an effect at the edge of
//          significance, and both halves double the trials the test sees (measured on the independent
//          generator's Schelleng sets, seed 31: hertz contact +26.5 %, p 0.0028 on the held-out half against
//          a bar of 0.0017; cross-fitted +32 %, p 5e-5, named; seed 36, damping: +25 %, p 0.0023 on one
//          half, +16 %, p 0.0039 over both, not named: the second half did not bear the first out). The
//          two routes share alpha (each alpha / 2), so the chance of naming an effect that does not help
//          stays below alpha whatever the screen: an effect is named only where one of two tests at
//          alpha / 2 rejects. The halves' fits depend on each other's trials only through an effect's few
//          parameters, which the sign-flip test treats as independent (the usual caveat of a
//          cross-validated test; the negative controls check it).
//   Signature: a candidate both tests leave short is significant by its signature (SignatureTest.h) when
//          z >= 4, the gain is at least 10 % and p < 0.2 (admitBySignature): a matched filter with smooth
//          bias projected out is the evidence the paired test, which sees only how much the objective fell,
//          lacks. This route is not inside alpha: its false-alarm rate is what the negative controls of the
//          tuning split measure (none of 8; Resources/docs/discover.md).
//   Stop:  after three effects, when no candidate is significant, or when the held-out gap of the model with
//          the adopted effects is 0 (within the measurement's scatter on every feature).
// JUCE-free.
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "lab/discovery/Dataset.h"
#include "lab/discovery/EffectCatalog.h"
#include "lab/discovery/ScanGrid.h"
#include "lab/discovery/SimulationModel.h"
#include "lab/discovery/discover/Calibration.h"
#include "lab/discovery/discover/GapMeasure.h"
#include "lab/discovery/discover/PairedTest.h"
#include "lab/discovery/discover/SearchInputs.h"
#include "lab/discovery/discover/SignatureTest.h"

namespace rosin::discovery
{

inline constexpr double kSignificanceLevel = 0.01;
inline constexpr double kMinRelativeGain = 0.2;
/// The share of alpha the held-out half alone decides with; the cross-fit has the rest.
inline constexpr double kHalfDecides = 0.5;
/// A candidate is cross-fitted when its held-out half gives p below this and a gain of at least this.
inline constexpr double kCrossFitScreenP = 0.05;
inline constexpr double kCrossFitScreenGain = 0.1;
/// A candidate the paired test leaves short of alpha is significant by its signature (SignatureTest.h) when
/// the held-out residual lies along it at least this many standard errors beyond a smooth model-form bias,
/// its held-out gain is at least kSignatureMinGain and the paired test gives p below kSignatureScreenP. The
/// gain and the test keep a signature that only follows the residual's structure from naming an effect that
/// makes the fit worse; all three are set on the tuning split (Resources/docs/discover.md).
inline constexpr double kSignatureZ = 4.0;
inline constexpr double kSignatureMinGain = 0.1;
inline constexpr double kSignatureScreenP = 0.2;

/// The checkerboard split of the valid trials (grid cells) into training and held-out halves.
void splitTrials(const ScanGrid& grid, std::vector<std::size_t>& training, std::vector<std::size_t>& heldOut);

struct EffectScore
{
    const Effect* effect = nullptr;
    std::vector<double> values;
    NuisanceValues nuisance; ///< the calibration as refitted together with the effect
    int evaluations = 0;
    /// Over the held-out half, or over both halves where the candidate was cross-fitted.
    double heldOutGain = 0.0;
    double pValue = 1.0;
    bool crossFitted = false;
    bool significant = false;
    /// False when the fit ended at the effect's null (Effect::atNull): the model it scores is the current
    /// one with the nuisance refitted, so its gain is the refit's, not the effect's; never significant.
    bool leftNull = true;
    GapSummary heldOutBefore, heldOutAfter;
    std::vector<double> heldOutShares; ///< each held-out trial's share of the objective with the effect
    /// The held-out residual along the fitted model's change to the current model's features (the effect
    /// and the nuisance refitted with it), smooth bias projected out (SignatureTest.h); 0 for a fit at its
    /// null.
    SignatureScore signature;
    /// Significant by the signature rule (kSignatureZ), the paired test alone falling short.
    bool bySignature = false;
};

/// The signature rule: a candidate that left its null and that the paired test left short becomes
/// significant (and bySignature) when its signature z, held-out gain and p pass kSignatureZ,
/// kSignatureMinGain and kSignatureScreenP; a significant candidate or one at its null is left as it is.
void admitBySignature(EffectScore& s);

/// The runner-up of a step: the best other candidate that was significant too, and the paired sign-flip
/// test between the two on the held-out trials (the chosen one's shares against the rival's). Two effects
/// of the catalog can leave alike traces in a scan (a saturating ageing with a long onset and a margin
/// released by the first slip both raise mostly the first slip's static friction), and a user must see when
/// the data named one only by a hair.
struct StepRival
{
    std::size_t index = 0; ///< into SearchStep::tried
    PairedTestResult test; ///< one-sided: the chosen effect explains the held-out trials better
    bool decided() const noexcept { return test.pValue < kSignificanceLevel; }
};

struct SearchStep
{
    EffectScore chosen;
    std::vector<EffectScore> tried; ///< every candidate of the step, in catalog order
    double alpha = kSignificanceLevel;
    SimulationModel model;          ///< the model after the step (the effect applied)
    std::optional<StepRival> rival; ///< none when no other candidate was significant
};

struct SearchResult
{
    std::vector<SearchStep> steps;      ///< adopted effects, in order
    std::vector<EffectScore> lastTried; ///< candidates of the step that adopted nothing (empty if none)
    double lastAlpha = kSignificanceLevel;
    SimulationModel model; ///< baseline + adopted effects
};

/// Where the first step's effects are fitted from: the stated values `uncalibrated`, because a calibration
/// may have bent the rig's parameters to mimic an effect (rosin constants mimic a warmer rosin), and so do
/// the `active` ones, which are refitted with each effect (CalibrationResult::active). The parameters no
/// effect can take the form of (NuisanceParameter::startsCalibrated: the measurement chain's gain, low-pass
/// and lag, the string's tension) keep their `calibrated` values where they are not active: an effect fitted
/// without the low-pass or the tuning the calibrated baseline already has would carry a misfit it cannot
/// mend (measured: on an independent string drawn at tension x1.0117, the first effect's fit from the
/// stated tension left the pitch's gap at 3.4, where the calibration had brought it to 0.8).
NuisanceValues effectStartNuisance(const NuisanceValues& uncalibrated, const NuisanceValues& calibrated,
                                   const std::vector<std::size_t>& active);

/// `baseline` is the calibrated baseline, `uncalibrated` its nuisance values before calibration; the first
/// step's effects start at effectStartNuisance.
SearchResult searchEffects(const SearchInputs& inputs, const SimulationModel& baseline,
                           const NuisanceValues& uncalibrated, const std::vector<std::size_t>& active);

/// Why the evidence points to the effect, in words (held-out features that improved, the test).
std::string describeEvidence(const EffectScore& score, double alpha);

/// The best significant candidate in `tried` other than `chosen` and the paired sign-flip test of the
/// chosen one against it on their held-out shares (trials where both are 0 left out); none when no other
/// candidate was significant. `seed` seeds the test's flips.
std::optional<StepRival> rivalOf(const std::vector<EffectScore>& tried, const EffectScore& chosen,
                                 std::uint64_t seed);

/// The runner-up in words ("" when there is none): its gain, the test between the two, and whether the data
/// decide between them.
std::string describeRival(const SearchStep& step);

} // namespace rosin::discovery
