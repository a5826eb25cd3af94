#pragma once
// The features rosin discover compares per trial, computed the same way from a measured and a simulated
// bridge force (force only, as a laboratory has it; the simulation passes through the dataset's sensor
// high-pass first). A feature a trial does not show (no slip, no Helmholtz motion) is std::nullopt.
//
//   staticFriction   mu_s = F_br(just before the first slip) / ((1 - beta) N)
//   analysis::firstSlipFromBridgeForce jump             (F_br before the first fall - after it) / N (sensor
//   high-pass undone) creep            pre-slip shortfall against the rigid-sticking parabola F ~ t^2:
//                    1 - F(0.6 t1) / (0.36 F(t1)), F the high-pass-undone force averaged over +-5 % of t1
//                    around 0.6 t1, F(t1) the fitted force at the slip (0: rigid sticking; > 0: the force
//                    rises faster than t^2 late in the hold, as a creeping or ageing contact gives);
//                    not read where F(0.6 t1) is not between 0 and F(t1) (no rising pre-slip force)
//   firstSlipTime    t1, s (the slip at the bow: the first fall minus the travel time beta P / 2)
//   transientPeriods periods from t1 to lasting Helmholtz motion (analysis::measureTransient on the force's
//   slip
//                    onsets), capped at 20 ([Galluzzo2017]'s "not reached" counts as 20)
//   pitchCents       in Helmholtz motion: 1200 log2(P / P_m) over the regime's window (below), the
//                    flattening of the Helmholtz period (analysis::classifyFromBridgeForce's period refined
//                    to a fraction of a sample by analysis::refinedPeriod: one sample is 5.8 cents at a cello
//                    D)
//   harmonicTilt     in established Helmholtz motion (the last 40 % of the trial, after t_H + 2 P; the
//                    second half of a steady one): harmonics 25-60 against 1-4 of the bridge force, dB
//                    (analysis::harmonicTiltDb): how round the Helmholtz corner is, i.e. the string's losses
//                    against the friction's sharpening; the spectral decay of the harmonics, which is how
//                    the losses show while the bow stays on the string (no gesture of the format lets the
//                    string ring freely). Read in any regime, it is as chaotic as the regime and hides the
//                    losses: tried and dropped.
//   steadyLevel      steady trials only, in every regime, over the second half: the bridge force's rms about
//                    its linear trend against the ideal Helmholtz sawtooth's, 2 Z0 v_b / (beta sqrt 12)
//                    (Z0 = sqrt(T mu), v_b the bow's mean speed over the window), dB: how much of the bow's
//                    drive the string's motion keeps (losses, rounded corners, a gauge's gain lower it).
//                    Read in raucous and multiple-slip motion too, where a Schelleng scan has most of its
//                    cells (60 % of a 12 x 12 scan is raucous, 20 % Helmholtz): there it
//                    follows the friction and the losses as well, so a contact or damping effect shows
//                    beyond the few Helmholtz cells; a regime that differs between the two sides is the
//                    regime's evidence, the level compares the amplitudes as they are. In
//                    a constant-acceleration start the amplitude still lags the rising bow speed at the end
//                    of the trial (-1 to -15 dB across a Guettler grid, as chaotic as the transient): tried
//                    there and dropped.
//   slipFraction     where the dataset records bowPointVelocity, over the same window as harmonicTilt: the
//                    share of the time the string slips past the bow (analysis::slipFraction; beta in ideal
//                    Helmholtz motion, more as the corners round)
//   loopArea         where it also records frictionForce: the hysteresis loop's signed area in (v - v_b, f/N)
//                    per period over the mean bow speed (analysis::normalisedLoopArea; 0 for a friction
//                    curve)
//   regime           the regime of the bridge force over the last 40 % of the trial (from 20 periods
//                    after the first slip at the earliest; the second half of a steady trial):
//                    analysis::Regime as a number, compared as a category (same: z = 0; different: z = 3, as
//                    for a feature seen on one side only)
// The bow's velocity is the bowVelocity channel where recorded, else the gesture's nominal one.
// JUCE-free.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "lab/discovery/Dataset.h"

namespace rosin::discovery
{

enum Feature : std::size_t
{
    kStaticFriction,
    kJump,
    kCreep,
    kFirstSlipTime,
    kTransientPeriods,
    kPitchCents,
    kHarmonicTilt,
    kSteadyLevel,
    kSlipFraction,
    kLoopArea,
    kRegime,
    kFeatureCount
};

/// "staticFriction", ... (the JSON names).
const char* featureName(std::size_t feature) noexcept;
/// The unit of a feature, for reports ("" dimensionless).
const char* featureUnit(std::size_t feature) noexcept;
/// The smallest scatter a feature is credited with (its resolution), so a quantised or noise-free feature
/// does not divide by zero: 0.002 (mu_s, jump), 0.005 (creep), 0.1 ms, 0.5 periods, 1 cent,
/// 0.2 dB (tilt, level: a steady level is smooth over the grid, so its neighbours
/// credit it with almost no scatter, while two string models that agree within their tolerances differ by
/// 0.1-0.4 dB there; ours), 0.005 (slip fraction), 0.002 (loop area), 1
/// (regime: a category).
double featureResolution(std::size_t feature, double sampleRate) noexcept;

/// True for the features measured only in established Helmholtz motion (pitchCents, harmonicTilt,
/// slipFraction, loopArea).
bool describesHelmholtzMotion(std::size_t feature) noexcept;

/// True for a feature whose value names a category (the regime): compared as equal or not.
bool isCategorical(std::size_t feature) noexcept;

using TrialFeatures = std::array<std::optional<double>, kFeatureCount>;

/// What the analysis needs to know about the trial and the chain.
struct FeatureContext
{
    double sampleRate = 44100.0;
    double beta = 0.0899;
    double bowForce = 1.0; ///< N, nominal
    Gesture gesture = ConstantAcceleration{1.0};
    double periodSeconds = 0.0; ///< nominal P of the rig's string
    double highpassHz = 0.0;    ///< sensor high-pass to undo (0: none)
    double noiseRms = 0.0;      ///< sensor noise, N (the same threshold for measurement and simulation)
    double impedance = 0.0;     ///< Z0 = sqrt(T mu) of the rig's string, kg/s (0: no steadyLevel)
};

/// The bowed point's own channels, where a dataset has them (nullptr where not).
struct ContactSignals
{
    const std::vector<double>* bowPointVelocity = nullptr; ///< m/s
    const std::vector<double>* frictionForce = nullptr;    ///< N
    const std::vector<double>* bowVelocity = nullptr;      ///< m/s; nullptr: the gesture's nominal one
};

/// The features of one trial from its bridge force (N, as recorded) and, where recorded, its contact.
TrialFeatures computeTrialFeatures(const std::vector<double>& bridgeForce, const FeatureContext& context,
                                   const ContactSignals& contact = {});

/// The context of a dataset's trial.
FeatureContext featureContext(const Dataset& dataset, const Trial& trial);

} // namespace rosin::discovery
