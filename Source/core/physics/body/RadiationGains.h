#pragma once
// A program's correction of the body's radiated levels: a gain curve over frequency that scales each mode's
// radiation residue (BodyMode::radiationGain), so one instrument's recording can be matched without touching
// what the strings feel (the admittance, hence the playability) or the modes' frequencies and damping.
// The curve is a calibration, fitted to a recording (Resources/scripts/fit_body.py), never physics.
#include <vector>

#include "core/physics/body/BodyParameters.h"

namespace rosin::physics
{

struct RadiationGainPoint
{
    double frequencyHz = 1000.0;
    double gainDb = 0.0;
};

/// The curve's gain (dB) at f: linear in log frequency between its points (ascending in frequency), the end
/// points' gains beyond them; 0 for an empty curve.
double radiationGainDb(const std::vector<RadiationGainPoint>& curve, double frequencyHz) noexcept;

/// Sets every mode's radiationGain from the curve at its frequency.
void applyRadiationGains(BodyParameters& body, const std::vector<RadiationGainPoint>& curve);

} // namespace rosin::physics
