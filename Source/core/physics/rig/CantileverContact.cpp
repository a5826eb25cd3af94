// [Smith2000]'s contact for the thermal laws (CantileverContact.h).
#include "core/physics/rig/CantileverContact.h"

#include <cmath>
#include <stdexcept>

#include "core/physics/friction/FrictionCurves.h"
#include "core/physics/numeric/BracketedRoot.h"
#include "core/physics/rig/OscillatorRigParameters.h"
#include "core/physics/thermal/HeatBalance.h"

namespace rosin::physics
{

ContactMaterials cantileverMaterials()
{
    ContactMaterials m;
    m.stationary = materials::acrylic; // "a perspex wedge"
    // "a rosin-coated wooden rod": the cylinder that "moves across it carrying a layer of rosin". Heat
    // reaches sqrt(kappa t) ~ 20 um into it in the ~5 ms a patch spends under the contact, no more than such
    // a coat, so its surface is taken as rosin [A]. (Bare wood, K 0.16, rho c 0.88e6: 71 Hz instead of 55
    // Hz.)
    m.moving = materials::rosin;
    return m;
}

ContactParameters cantileverContact()
{
    ContactParameters p;
    p.materials = cantileverMaterials();
    // Calibration ([Smith2000]'s own): contactRadiusForSteadyTemperature(55 K, 0.042 m/s, 6.3 N, 10 um,
    // cantileverMaterials()) = 0.410 mm.
    p.rig = ContactGeometry{0.410e-3, CantileverLoad::normalForce, 10e-6, ContactScaling::Coulomb};
    p.calibration = p.rig; // [Smith2000]: the steady-sliding curve was measured on these surfaces
    return p;
}

double steadySlidingTemperature(const ContactParameters& contact, double speed, double normalForce)
{
    const double v = std::abs(speed);
    const double power = normalForce * ClassicalCurve{}.mu(v) * v;
    return power / HeatBalance::steadyConductance(contact.rig, contact.materials, normalForce, v);
}

double contactRadiusForSteadyTemperature(double targetKelvin, double speed, double normalForce,
                                         double layerThickness, const ContactMaterials& materials)
{
    auto temperature = [&](double radius)
    {
        ContactParameters c;
        c.rig = ContactGeometry{radius, normalForce, layerThickness, ContactScaling::Coulomb};
        c.materials = materials;
        return steadySlidingTemperature(c, speed, normalForce);
    };
    double small = 1e-6, large = 0.01; // m
    if (!(temperature(small) > targetKelvin && temperature(large) < targetKelvin))
        throw std::runtime_error(
            "contactRadiusForSteadyTemperature: target not reachable with radii 1 um..10 mm");
    return bisectGeometric([&](double radius) { return temperature(radius) > targetKelvin; }, small, large,
                           1e-10, 100);
}

} // namespace rosin::physics
