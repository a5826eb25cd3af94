#pragma once
// How far two string models with the same physics still disagree after calibration, per feature: the
// model-form tolerance of the verdict. The verdict asks whether what remains after calibration and
// the adopted effects is more than the measurement's scatter explains; against a measurement that no model
// of this one's form made, "the scatter" must include what any second model with the same physics would
// leave. Measured, not assumed, and never fitted to the dataset being judged: Rosin against the tuning split
// of the independent generator's family (`rosin synth-data --generator independent --member K`, members
// 1-20: other numerics, constants, chains and rigs, GeneratorMember.h) with nothing hidden, a Guettler scan
// (10 x 10 x 2, betas 0.0899 and 0.12) and a Schelleng scan (12 x 12) of each, seeds 201-220, calibrated as
// rosin discover calibrates. Per feature and dataset, tau is the smallest widening at which the verdict's own
// statistic, the mean of min(z^2, 9), falls to its null value 1; the tolerance is the largest over the forty
// datasets, so that every tuning member's control is clean (`Resources/scripts/model_form_tolerance.py`
// prints the table from the datasets' maps.json). What sets each:
//   * pitch 6.3 cents: mostly a constant offset, the generator's string drawn up to 1.5 % tenser and 1 %
//     heavier than stated (the offsets of members 1-8 match the drawn constants within 0.6 cents on the
//     Guettler scans). The calibration fits the tension, but the pre-slip rise and the first slip pin it and
//     it stays at the stated value; a mass-per-length prior in the calibration did not move either;
//   * harmonic tilt 2.4 dB: every member, 0.7-2.4 dB;
//   * steady level 1.4 dB: 18 of 20 Schelleng controls, 0.4-1.3 dB;
//   * first-slip time 2.2 ms, transient 3.1 periods, static friction 0.0099, jump 0.021, creep 0.0088: a few
//     of the Guettler controls each (most leave them within the scatter); the largest first-slip time and
//     jump come from member 12, whose control the search wrongly explains by extra internal damping.
// The sealed split (members from 100) is scored with this table, never used to set it. It is a calibration
// of the verdict against a family of second models, not a reproduction of anything; a bowing machine will
// differ from both by at least this much.
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
