// Plastic thermal friction law (seed 000 eq. 4; reference §2.1-2.2, §2.5).
#include "PlasticThermalLaw.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rosin::physics
{

void PlasticThermalLaw::prepare(double sampleRate)
{
    heat_.prepare(contact_, sampleRate);
    table_.build(contact_, sampleRate, CalibrationQuantity::YieldStress);
    prepared_ = true;
    reset();
}

void PlasticThermalLaw::reset() noexcept
{
    heat_.reset();
    previousPower_ = 0.0;
    previousSpeed_ = 0.0;
}

double PlasticThermalLaw::yieldStress(double T) const noexcept
{
    return table_.lookup(T + contact_.ambientOffset);
}

double PlasticThermalLaw::frictionLimit(double T, double bowForce) const noexcept
{
    const double a = contact_.rig.radiusAt(bowForce);
    return yieldStress(T) * std::numbers::pi * a * a;
}

double PlasticThermalLaw::staticCoefficient(double bowForce) const noexcept
{
    const double Fb = std::max(bowForce, HeatBalance::kMinimumBowForce);
    return frictionLimit(heat_.temperature(), Fb) / Fb;
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
    const double dvh = std::isfinite(in.dvHistory) ? in.dvHistory : 0.0;
    const double Fb = std::isfinite(in.bowForce) ? std::max(in.bowForce, 0.0) : 0.0;
    const double twoZ = in.loadSlope;
    if (!prepared_)
        return {dvh, 0.0, false};
    // Predictor: temperature with last sample's power (Woodhouse's order, one-sample lag).
    const double Tpred = heat_.predict(previousPower_, previousSpeed_, Fb);
    JunctionSolution s = solveCharacteristic(dvh, twoZ, frictionLimit(Tpred, Fb));
    // Corrector: temperature with this sample's power, solve once more (reference §2.5 refinement).
    const double Tcorr = heat_.predict(std::abs(s.frictionForce * s.dv), std::abs(s.dv), Fb);
    s = solveCharacteristic(dvh, twoZ, frictionLimit(Tcorr, Fb));
    previousPower_ = std::abs(s.frictionForce * s.dv);
    previousSpeed_ = std::abs(s.dv);
    heat_.commit(previousPower_, previousSpeed_, Fb);
    return s;
}

} // namespace rosin::physics
