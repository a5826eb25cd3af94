// Plastic thermal friction law ([Smith2000] eq. 4; [Notes §2.1-2.2], §2.5).
#include "core/physics/thermal/PlasticThermalLaw.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rosin::physics
{

void PlasticThermalLaw::prepare(double sampleRate)
{
    thermal_.prepare(sampleRate, CalibrationQuantity::YieldStress);
}

void PlasticThermalLaw::reset() noexcept
{
    thermal_.reset();
}

double PlasticThermalLaw::yieldStress(double T) const noexcept
{
    return thermal_.property(T);
}

double PlasticThermalLaw::frictionLimit(double T, double bowForce) const noexcept
{
    return yieldStress(T) * thermal_.area(bowForce);
}

double PlasticThermalLaw::staticCoefficient(double bowForce) const noexcept
{
    const double Fb = std::max(bowForce, HeatBalance::kMinimumBowForce);
    return frictionLimit(thermal_.temperature(), Fb) / Fb;
}

JunctionSolution PlasticThermalLaw::solveCharacteristic(double dvh, double twoZ, double limit) noexcept
{
    if (std::abs(twoZ * dvh) <= limit)
        return {0.0, -twoZ * dvh, true}; // stick: the bow supplies whatever force holds dv = 0
    const double side = dvh > 0.0 ? 1.0 : -1.0;
    return {dvh - side * limit / twoZ, -side * limit, false}; // slide at f = -sgn(dv) limit
}

JunctionSolution PlasticThermalLaw::solve(const JunctionInput& in) noexcept
{
    return step(in, 0.0);
}

JunctionSolution PlasticThermalLaw::solveCreeping(const JunctionInput& in, double eta) noexcept
{
    return step(in, eta);
}

JunctionSolution PlasticThermalLaw::step(const JunctionInput& in, double creepResistance) noexcept
{
    JunctionInput safe = in;
    safe.dvHistory = std::isfinite(in.dvHistory) ? in.dvHistory : 0.0;
    const double dvh = safe.dvHistory;
    const double Fb = std::isfinite(in.bowForce) ? std::max(in.bowForce, 0.0) : 0.0;
    const double twoZ = in.loadSlope;
    if (!thermal_.prepared())
        return {dvh, 0.0, false};
    if (Fb == 0.0)
    {
        // Bow lifted: the contact area pi a(0)^2 is zero, so the limit is zero at any temperature, and the
        // open contact moves no heat (HeatBalance::open).
        const JunctionSolution s =
            creepingSolution(solveCharacteristic(dvh, twoZ, 0.0), safe, creepResistance);
        thermal_.open();
        return s;
    }
    // A held contact creeps where a creep resistance is given (creepingSolution; 0: none), so the
    // corrector sees the creep's power and the commit takes it.
    // Predictor: temperature with last sample's power (Woodhouse's order, one-sample lag).
    JunctionSolution s = creepingSolution(
        solveCharacteristic(dvh, twoZ, frictionLimit(thermal_.predict(Fb), Fb)), safe, creepResistance);
    // Corrector: temperature with this sample's power, solve once more ([Notes §2.5] refinement).
    s = creepingSolution(solveCharacteristic(dvh, twoZ, frictionLimit(thermal_.predict(s, Fb), Fb)), safe,
                         creepResistance);
    thermal_.commit(s, Fb);
    return s;
}

} // namespace rosin::physics
