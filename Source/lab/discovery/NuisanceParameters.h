#pragma once
// What a laboratory knows about its rig and its measurement chain only to a tolerance:
// rosin discover calibrates these within their priors before it attributes anything to an effect. Each
// changes the model's numbers within what the lab would quote; none changes its structure (how friction
// depends on hold time, force or temperature), which is what the EffectCatalog's effects do, so calibration
// cannot swallow an effect by its form; within its range it can mimic part of one (a smaller contact
// lowers the friction force as a warmer rosin does), which is why the ranges are what a lab would quote and
// no wider. Priors (min..max; factors on the nominal value unless a unit is given):
//   contactRadius       0.87..1.15  the contact radius a_ref: estimated from a contact mark, not measured
//                                   ([Galluzzo2017] Table 2 gives one value per rig)
//   rosinConductivity   0.83..1.2   the rosin's K: handbook values for rosin and similar resins scatter by
//   rosinHeatCapacity   0.83..1.2   about this much ([Notes §2.6]), rho c likewise
//   tension             0.98..1.02  the string's tension: a lab tunes the string, so 2 % (35 cents)
//   stringLoss          0.83..1.2   every transverse loss factor: the loss law's fit to the measured decays
//                                   ([Galluzzo2017] Table 1) is good to about this
//   sensorGain          0.97..1.03  the force gauge's sensitivity, as calibrated
//   sensorBandwidth     0.2..0.5    the chain's low-pass corner (anti-aliasing, gauge resonance) over the
//                                   sample rate, modelled as a second-order Butterworth; 0.5 (Nyquist) is
//                                   none. A dataset states the high-pass it had but never its low-pass.
//   sensorDelay         0..1.5 ms   how late the force channels are after the gesture: a trigger's latency
//                                   (the format puts time zero at the gesture's start, which a lab knows to
//                                   about a millisecond) and the force chain's own lag behind the recorded
//                                   bow velocity, which the features align each trial to where they can
//                                   (GestureStart); the pre-slip rise's shape reads it (creep).
// The physical ones act through SimulationModel (voiceConfig, frictionLaw), the sensor's in rosin discover's
// simulation of the measurement chain (ModelRuns). JUCE-free.
#include <cstddef>
#include <string>
#include <vector>

#include "lab/discovery/EffectParameter.h"

namespace rosin::discovery
{

struct NuisanceValues
{
    double contactRadius = 1.0;
    double rosinConductivity = 1.0;
    double rosinHeatCapacity = 1.0;
    double tension = 1.0;
    double stringLoss = 1.0;
    double sensorGain = 1.0;
    double sensorBandwidth = 0.5;
    double sensorDelay = 0.0; ///< s

    bool operator==(const NuisanceValues&) const = default;
};

struct NuisanceParameter
{
    EffectParameter prior;         ///< name, unit, range (min..max), log scale, meaning
    double NuisanceValues::*value; ///< where it is kept
    /// The sensor's (gain, low-pass, lag) rather than the rig's physics: a linear chain after the string,
    /// which cannot take the form of a friction effect, so an effect's fit may start from its calibration.
    bool measurementChain = false;
    /// No effect of the catalog can take this parameter's form, so an effect's fit starts from its
    /// calibrated value (EffectSearch): the measurement chain's, and the string's tension, i.e. its tuning.
    /// The catalog's effects act at the contact (friction, its area, creep, the rosin's temperature) or on
    /// the losses; none retunes the string, whose Helmholtz pitch pins the tension to a few cents
    /// wherever Helmholtz motion is measured. Left at its stated value instead, a tension the calibration
    /// had found (x1.01 on an independent string drawn at x1.0117) was lost with the first effect, and the
    /// pitch's gap returned (3.4 after calibration had brought it to 0.8).
    bool startsCalibrated = false;
    double nominal() const { return NuisanceValues{}.*value; }
};

/// The eight parameters in the order above.
const std::vector<NuisanceParameter>& nuisanceParameters();

/// Whether `prior` is the prior of one of the measurement chain's parameters (by identity, not by name: an
/// effect may name a parameter alike).
bool isMeasurementChain(const EffectParameter& prior) noexcept;

/// The low-pass corner in Hz that `values` give at `sampleRate`; 0 when it is at Nyquist (no filter).
double sensorLowpassHz(const NuisanceValues& values, double sampleRate) noexcept;

/// The start delay in whole samples at `sampleRate`.
std::size_t sensorDelaySamples(const NuisanceValues& values, double sampleRate) noexcept;

/// "contactRadius x0.91, sensorGain x1.02, ..." for the ones away from nominal ("nominal" if none).
std::string describeNuisance(const NuisanceValues& values);

} // namespace rosin::discovery
