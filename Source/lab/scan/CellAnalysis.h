#pragma once
// From one trial's per-sample output to its scan.csv row, with the lab's analyses ([Notes §7]):
//  * the first slip from the solver's state (analysis::firstSlipFromState): mu_s, the jump, its time;
//  * the steady regime over the end of the trial (analysis::classifyFromVoice, flybacks only): Guettler the
//  last
//    20 nominal periods, Schelleng the second half of the time after the ramp (at least 20 periods). A
//    Guettler trial normally ends once its transient is decided (ScanSpec::trialEnd, TrialEnd.h): with its
//    transient window, or sooner once the transient can no longer start within the cap, so its regime is
//    that of the 20 periods before that point, the motion the transient reached, or the motion in which it
//    missed;
//  * the transient (analysis::measureTransient on the full flybacks, [Notes §7.3]: 5 % period tolerance, a
//  run
//    of >= 5 Helmholtz periods lasting to the end of the analysed window, cap 20 periods). The window is the
//    first 40 periods after the first slip (see addTransient); fewer than 20 periods of trial after the first
//    slip leave the transient empty ([Galluzzo2017]'s "x" pixels). Slip durations are not checked: the
//    thermal laws end a flyback gently, and their steady flybacks last up to ~2 beta P (the "loose" limit of
//    [Notes §7.3]), so the check rejected steady Helmholtz motion of the plastic law. The period is the one
//    measured over the window's second half when that is one-slip-per-period motion within +-10 % of the
//    nominal P (Helmholtz or S-motion: near F_max a string on a body is flattened by a few %, which the 5 %
//    tolerance about the nominal P would count as failure), else the nominal P = 1/f0.
// With Classification::BridgeForce the regime and the transient come from the bridge force alone, with the
// analyses a measurement gets (analysis::classifyFromBridgeForce, analysis::slipOnsetsFromBridgeForce and the
// same [Notes §7.3] transient rule on those onsets, the window anchored at the first onset); the first slip
// stays the solver's (the bridge-force first-slip analysis needs the high-pass a measurement has).
#include <cstddef>
#include <vector>

#include "core/physics/voice/BowedStringVoice.h"
#include "lab/scan/CellResult.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

/// A flyback counts in the transient when the string slips back at >= this share of v_b / beta (the ideal
/// Helmholtz flyback; analysis::fullFlybacksOnly). [Galluzzo2017] counts the slips a bridge-force analysis
/// sees, and the plastic law's short reversals at a slow bow (found in its Guettler scans: a few % of v_b /
/// beta, and each one broke a Helmholtz run) are not such slips. The Guettler ranking of the three laws at
/// beta 0.0899 is the same for any share in 0.15-0.35 (tests/lab/scan/GuettlerScanTest.cpp); the friction
/// curves' fractions do not move over that range.
inline constexpr double kFlybackShare = 0.25;

/// Periods of the Guettler steady-regime window, and the least a Schelleng window may have.
inline constexpr double kSteadyWindowPeriods = 20.0;
/// [Galluzzo2017]'s cap: transients of 20 periods or more are "not reached".
inline constexpr double kTransientCapPeriods = 20.0;

struct TrialContext
{
    ScanKind kind = ScanKind::Guettler;
    CellSettings cell;
    double sampleRate = 48000.0;
    double periodSamples = 0.0; ///< nominal P = fs / f0
    std::size_t rampEnd = 0;    ///< first sample at the final bow speed (Schelleng)
    Classification classification = Classification::State;
};

CellResult analyseTrial(const std::vector<physics::VoiceSample>& samples, const TrialContext& context);

} // namespace rosin::scan
