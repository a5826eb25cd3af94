#pragma once
// Offline runs of the oscillator rig and the calibrations [Smith2000] leaves to the reader (allocates;
// never on the audio thread):
// - the modal mass m, not given in [Smith2000], chosen so that the traditional curve ([Smith2000] eq. 2,
//   Rosin's "classical" law) gives stick-slip at the reported 34 Hz;
// - the cantilever contact (CantileverContact.h), whose radius makes steady sliding at the rod speed run at
//   [Smith2000]'s ~55 K above ambient;
// - and one constant [Smith2000] calls uncertain: rosin's heat capacity (RosinMaterial.h), chosen so that the
//   plastic law gives the reported ~44 Hz.
#include <functional>
#include <memory>
#include <vector>

#include "core/physics/rig/OscillatorRig.h"

namespace rosin::physics
{

/// A run of the rig at constant load and rod speed from rest (the rod starts at full speed, as a rod on an
/// air bearing pulled by a weight does once released).
struct RigRun
{
    double sampleRate = 48000.0;
    std::vector<RigSample> samples;
};

RigRun runRig(const OscillatorRigParameters& rig, std::unique_ptr<FrictionLaw> law, double sampleRate,
              double normalForce, double rodSpeed, double seconds);

/// Times (s) at which slipping starts (stick -> slip) at or after `fromSeconds`.
std::vector<double> slipOnsetTimes(const RigRun& run, double fromSeconds);
/// Stick-slip frequency (Hz) from the mean spacing of slip onsets at or after `fromSeconds`; 0 if fewer than
/// three onsets (no sustained stick-slip).
double stickSlipFrequency(const RigRun& run, double fromSeconds);

/// Modal mass (kg) for which the classical curve gives stick-slip at `targetHz` on `rig` (its frequency and
/// Q) under [Smith2000]'s load and rod speed: bisection on log m over [lowKg, highKg], where the frequency
/// rises with m (a stiffer spring reaches the breakaway force sooner). Throws std::runtime_error if the
/// target is not bracketed.
double calibrateModalMass(const OscillatorRigParameters& rig, double targetHz, double sampleRate,
                          double lowKg = 0.005, double highKg = 0.1);

/// Factor on the handbook rosin's rho c (RosinMaterial.h) for which the plastic law on [Smith2000]'s rig
/// settles at `targetHz` (slip onsets over 1-2 s of a 2 s run), the contact kept as cantileverContact() sized
/// it: bisection on log factor over [low, high], where the frequency falls with the factor (56 Hz at 1x,
/// 42.7 Hz at 4x). Throws std::runtime_error if the target is not bracketed.
double calibrateRosinHeatCapacity(double targetHz, double sampleRate, double low = 1.0, double high = 4.0);

} // namespace rosin::physics
