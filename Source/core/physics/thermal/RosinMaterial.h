#pragma once
// Which rosin the contact is made of. [Smith2000] took rosin's thermal constants from Cobbold and Jackson,
// "who pointed out that their determination of the diffusivity, and hence the specific heat capacity, was not
// very accurate", noted that comparable materials such as paraffin wax lie an order of magnitude higher, and
// re-ran its rig with a higher value. Rosin's volumetric heat capacity is therefore an uncertain material
// constant with a prior of 1x to 10x the handbook value (ThermalMaterial.h); its conductivity, which
// [Smith2000] does not question, stays the handbook value.
//  * handbook: the handbook rosin, fitted to nothing;
//  * calibrated: rho c x kCalibratedRosinHeatCapacityFactor, a calibration against one seed statement,
//    [Smith2000]'s plastic-law stick-slip at ~44 Hz (calibrateRosinHeatCapacity in rig/RigCalibration.h).
// One rosin for every contact: the softened layer and every solid surface that is a rosin coat.
#include <string>
#include <vector>

#include "core/physics/thermal/ThermalMaterial.h"

namespace rosin::physics
{

enum class RosinMaterial
{
    Handbook,
    Calibrated
};

/// Calibration, not a prediction: the factor on the handbook rho c for which [Smith2000]'s rig (its contact
/// sized with the handbook rosin, as the seed sized it before re-running with a higher heat capacity) settles
/// at 44 Hz with the plastic law (slip onsets over 1-2 s of a 2 s run at 48 kHz). The lower of the two roots
/// in the 1-10 prior: the frequency falls to 41.7 Hz at 5x and rises again to 47.7 Hz at 10x.
inline constexpr double kCalibratedRosinHeatCapacityFactor = 3.17;

/// The handbook rosin with its volumetric heat capacity multiplied by `factor`.
ThermalMaterial rosinWithHeatCapacityFactor(double factor);
ThermalMaterial rosinMaterial(RosinMaterial which);

/// `m` with every handbook-rosin member (layer and rosin-coated sides) replaced by `rosin`.
ContactMaterials withRosin(ContactMaterials m, const ThermalMaterial& rosin);

/// "handbook", "calibrated".
const std::vector<std::string>& rosinMaterialNames();
/// Throws std::invalid_argument for a name not in rosinMaterialNames().
RosinMaterial rosinMaterialFromName(const std::string& name);

} // namespace rosin::physics
