#pragma once
// How far two string models with the same physics still disagree after calibration, per feature: the
// model-form tolerance of the verdict. The verdict asks whether what remains after calibration and
// the adopted effects is more than the measurement's scatter explains; against a measurement that no model
// of this one's form made, "the scatter" must include what any second model with the same physics would
// leave. Measured, not assumed: Rosin against the project's independent generator (a digital waveguide with
// its own heat balance, `rosin synth-data --generator independent`) on Schelleng scans (12 x 12) with nothing
// hidden, drawn with seeds 17 and 23, which neither the discover page's tables nor a test uses: tau^2 =
// mean(d^2 - sigma^2) over the 50 trials where the calibrated model and the measurement both show Helmholtz
// motion, d = measured - model, sigma the trial's scatter. The pitch's part is not the tension: seed 17's
// string plays 2.66 cents flatter than the calibrated model (mean; tension x1.02, drawn x1.0185), yet a
// tension step matching the median pitch difference did not lower the training objective on seeds 17, 23
// or 31 (tried in the calibration, withdrawn).
// The steady level (read in every regime) was first left at 0: over seeds 17 and 23 its differences stayed
// within the scatter (mean z^2 0.85 over 280 trials, as calibrated then). Re-measured
// over six sets (seeds 17, 23, 41, 43, 47, 53; none is the discover page's seed 31 or a test's), calibrated
// as rosin discover calibrates now, with the sigma that includes each trial's sensitivity: tau^2 per seed
// 0.33, -0.20, 0.53, 0.16, -0.18, 0.30 dB^2 (140 trials each), pooled 0.156, tau 0.4 dB; the same six sets
// give 2.0 cents for the pitch and 1.50 dB for the tilt (pooled over 152 trials), as below. Without it the
// verdict on such a set turned on the calibration's pick between near-equal optima (seed 43: p 9e-5; seed
// 31: 0.0075 on x86-64-v4, 0.16 on x86-64-v3). Features of the attack (first slip,
// transient) are left at 0: on Guettler scans with nothing hidden the calibrated model is already within
// their scatter. It is a calibration of the verdict against one second model, not a reproduction of
// anything; a bowing machine will differ from both models by at least this much.
//
// Only the verdict (no-significant-discrepancy or unexplained) uses it: fits, the paired test that names an
// effect and the gaps reported stay in units of the measurement's own scatter, so a systematic misfit that
// an effect explains counts in full there. The report gives the gaps in its units too, beside them
// (`gapBeyondModelForm`): how much of a gap no second model of the same physics would leave anyway.
// JUCE-free.
#include <array>

#include "lab/discovery/discover/FeatureScatter.h"
#include "lab/discovery/discover/TrialFeatures.h"

namespace rosin::discovery
{

/// tau per feature, in the feature's unit (0: none measured beyond the scatter).
const std::array<double, kFeatureCount>& modelFormTolerance() noexcept;

/// `scatter` with every feature's sigma widened to sqrt(sigma^2 + tau^2) (a category keeps its rate).
FeatureScatter withModelFormTolerance(FeatureScatter scatter);

} // namespace rosin::discovery
