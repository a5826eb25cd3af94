// Contact geometry as a function of the normal force, and the two bowing-rig contacts of [Galluzzo2017]
// Table 2.
#include "core/physics/thermal/ContactParameters.h"

#include <algorithm>
#include <cmath>

namespace rosin::physics
{

/// Contact radius a(N), m, for a normal force N in newtons (negative forces give a = 0).
///   Coulomb ([Galluzzo2017] Table 2 caption): a = a_ref sqrt(N / N_ref), so A = pi a^2 grows in proportion
///   to N. Hertz ([Notes §8.3], single elastic contact): a = a_ref (N / N_ref)^(1/3), so A ~ N^(2/3).
double ContactGeometry::radiusAt(double normalForce) const
{
    const double ratio = std::max(normalForce, 0.0) / referenceForce;
    return scaling == ContactScaling::Coulomb ? radius * std::sqrt(ratio) : radius * std::cbrt(ratio);
}

/// [Galluzzo2017] Table 2, "Galluzzo rig": 250 um at 1 N, 1 um layer; calibration rig 500 um at 3 N, 10 um.
ContactParameters galluzzoContact()
{
    ContactParameters p;
    p.rig = ContactGeometry{250e-6, 1.0, 1e-6, ContactScaling::Coulomb};
    p.calibration = ContactGeometry{500e-6, 3.0, 10e-6, ContactScaling::Coulomb};
    return p;
}

/// [Galluzzo2017] Table 2, "Schumacher rig": 200 um at 1 N, 1 um layer; same calibration rig.
ContactParameters schumacherContact()
{
    ContactParameters p;
    p.rig = ContactGeometry{200e-6, 1.0, 1e-6, ContactScaling::Coulomb};
    p.calibration = ContactGeometry{500e-6, 3.0, 10e-6, ContactScaling::Coulomb};
    return p;
}

} // namespace rosin::physics
