// Seed 000's contact for the thermal laws (CantileverContact.h).
#include "CantileverContact.h"

#include <cmath>
#include <stdexcept>

#include "../friction/FrictionCurves.h"
#include "../thermal/HeatBalance.h"
#include "OscillatorRigParameters.h"

namespace rosin::physics
{

ContactParameters cantileverContact()
{
    ContactParameters p;
    // 0.59 mm: contactRadiusForSteadyTemperature(55 K, 0.042 m/s, 6.3 N, 10 um, default material) = 0.590 mm.
    p.rig = ContactGeometry{0.59e-3, CantileverLoad::normalForce, 10e-6, ContactScaling::Coulomb};
    p.calibration = p.rig; // seed 000: the steady-sliding curve was measured on these surfaces
    return p;
}

double steadySlidingTemperature(const ContactParameters& contact, double speed, double normalForce)
{
    const double v = std::abs(speed);
    const double power = normalForce * ClassicalCurve{}.mu(v) * v;
    return power / HeatBalance::steadyConductance(contact.rig, contact.material, normalForce, v);
}

double contactRadiusForSteadyTemperature(double targetKelvin, double speed, double normalForce,
                                         double layerThickness, const ThermalMaterial& material)
{
    auto temperature = [&](double radius)
    {
        ContactParameters c;
        c.rig = ContactGeometry{radius, normalForce, layerThickness, ContactScaling::Coulomb};
        c.material = material;
        return steadySlidingTemperature(c, speed, normalForce);
    };
    double small = 1e-6, large = 0.01; // m
    if (!(temperature(small) > targetKelvin && temperature(large) < targetKelvin))
        throw std::runtime_error(
            "contactRadiusForSteadyTemperature: target not reachable with radii 1 um..10 mm");
    for (int it = 0; it < 100 && large / small > 1.0 + 1e-10; ++it)
    {
        const double mid = std::sqrt(small * large);
        (temperature(mid) > targetKelvin ? small : large) = mid;
    }
    return std::sqrt(small * large);
}

} // namespace rosin::physics
