#pragma once
// The rosin contact of [Smith2000]'s rig for the thermal laws. [Smith2000] measured the steady-sliding curve
// (eq. 2) on the same surfaces as the stick-slip runs (the wedge clamped rigidly), so here the calibration
// contact IS the rig contact: steady sliding on the rig reproduces eq. 2 exactly, and at ambient the plastic
// law's limiting coefficient equals the curve's 1.2 ([Notes §2.1] with equal area per newton).
// Its size follows [Smith2000]: "radius and thickness of the 'melted' layer ... determined by requiring that
// the contact temperature would be around 55 K above ambient during steady sliding at the assumed rod speed".
// One condition, two unknowns: the layer keeps [Galluzzo2017] Table 2's steady-sliding value (10 um) and the
// radius at the rig's 6.3 N is solved for (contactRadiusForSteadyTemperature;
// tests/core/physics/rig/CantileverContactTest.cpp).
#include "core/physics/thermal/ContactParameters.h"

namespace rosin::physics
{

/// [Smith2000]'s target: steady-sliding contact temperature at the rod speed, K above ambient.
inline constexpr double kCantileverSteadyTemperature = 55.0;

/// [Smith2000]'s solids: a rosin layer between the perspex wedge (stationary: the contact stays on it) and
/// the rosin coat of the wooden rod that slides through it.
ContactMaterials cantileverMaterials();

/// Rig and calibration contact: radius at 6.3 N from contactRadiusForSteadyTemperature (a calibration: the
/// seed's own condition, see above), 10 um layer, Coulomb scaling, cantileverMaterials().
ContactParameters cantileverContact();

/// Steady-sliding contact temperature rise (K) on `contact.rig` at sliding speed `speed` (m/s) and normal
/// force N: T = N mu(v) v / G_ss(v) ([Notes] eq. 2.7), with mu the steady-sliding curve of [Smith2000] eq. 2,
/// which the thermal laws reproduce in steady sliding when the rig is the calibration contact.
double steadySlidingTemperature(const ContactParameters& contact, double speed, double normalForce);

/// Radius (m) at N = referenceForce of a disc with `layerThickness` and `materials` whose steady-sliding
/// temperature at `speed` is `targetKelvin`; bisection (T falls as the disc grows: more area conducts).
double contactRadiusForSteadyTemperature(double targetKelvin, double speed, double normalForce,
                                         double layerThickness, const ContactMaterials& materials);

} // namespace rosin::physics
