#include "core/physics/thermal/ThermalContact.h"

#include <cmath>
#include <numbers>

namespace rosin::physics
{

void ThermalContact::prepare(double sampleRate, CalibrationQuantity quantity)
{
    heat_.prepare(contact_, sampleRate);
    table_.build(contact_, sampleRate, quantity);
    areaForce_ = -1.0;
    prepared_ = true;
    reset();
}

void ThermalContact::reset() noexcept
{
    heat_.reset();
    previousPower_ = 0.0;
    previousSpeed_ = 0.0;
}

double ThermalContact::predict(double bowForce) const noexcept
{
    return heat_.predict(previousPower_, previousSpeed_, bowForce);
}

double ThermalContact::predict(const JunctionSolution& trial, double bowForce) const noexcept
{
    return heat_.predict(std::abs(trial.frictionForce * trial.dv), std::abs(trial.dv), bowForce);
}

void ThermalContact::commit(const JunctionSolution& solution, double bowForce) noexcept
{
    previousPower_ = std::abs(solution.frictionForce * solution.dv);
    previousSpeed_ = std::abs(solution.dv);
    heat_.commit(previousPower_, previousSpeed_, bowForce);
}

void ThermalContact::open() noexcept
{
    previousPower_ = 0.0;
    previousSpeed_ = 0.0;
    heat_.open();
}

double ThermalContact::area(double bowForce) const noexcept
{
    if (bowForce != areaForce_)
    {
        const double a = contact_.rig.radiusAt(bowForce);
        areaForce_ = bowForce;
        area_ = std::numbers::pi * a * a;
    }
    return area_;
}

} // namespace rosin::physics
