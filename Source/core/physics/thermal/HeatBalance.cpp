// Implicit time marching of the contact heat balance ([Notes] eq. 2.4, 2.7, 2.9 and §2.3a).
#include "core/physics/thermal/HeatBalance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/physics/thermal/Washout.h"

namespace rosin::physics
{

namespace
{
double sanitiseNonNegative(double x) noexcept
{
    return std::isfinite(x) ? std::abs(x) : 0.0;
}
double clampForce(double f) noexcept
{
    return std::isfinite(f) ? std::max(f, HeatBalance::kMinimumBowForce) : HeatBalance::kMinimumBowForce;
}
} // namespace

void HeatBalance::prepare(const ContactGeometry& geometry, const ContactMaterials& materials,
                          double sampleRate)
{
    geometry_ = geometry;
    materials_ = materials;
    dt_ = 1.0 / sampleRate;
    stationary_.prepare(geometry.radius, materials.stationary, dt_);
    moving_.prepare(geometry.radius, materials.moving, dt_);
    forceTerms_ = {}; // new geometry, materials or time step
    localSpeed_ = localForce_ = std::numeric_limits<double>::quiet_NaN();
    reset();
}

void HeatBalance::reset() noexcept
{
    stationary_.reset();
    moving_.reset();
    temperature_ = 0.0;
    stationaryFlux_ = movingFlux_ = 0.0;
    atRest_ = true;
}

const HeatBalance::ForceTerms& HeatBalance::forceTerms(double bowForce) const noexcept
{
    const double F = clampForce(bowForce);
    if (F == forceTerms_.force)
        return forceTerms_;
    const double a = geometry_.radiusAt(F);
    const double area = std::numbers::pi * a * a;
    const double rhoC = materials_.layer.volumetricHeatCapacity;
    const double delta = geometry_.layerThickness;
    ForceTerms& t = forceTerms_;
    t.force = F;
    t.capacityRate = rhoC * area * delta / dt_;
    t.advectionPerSpeed = rhoC * materials_.advectionWidthRatio * a * delta;
    t.kernelScale = (geometry_.radius * geometry_.radius) / (a * a); // A_ref / A
    t.invStationaryG0 = 1.0 / (t.kernelScale * stationary_.firstStepWeight());
    t.invMovingG0 = 1.0 / (t.kernelScale * moving_.firstStepWeight());
    t.washoutPerSpeed = dt_ / (washout::kLengthPerRadius * a);
    return t;
}

const HeatBalance::Local& HeatBalance::local(double slidingSpeed, double bowForce) const noexcept
{
    if (slidingSpeed == localSpeed_ && bowForce == localForce_)
        return local_;
    const ForceTerms& t = forceTerms(bowForce);
    const double v = sanitiseNonNegative(slidingSpeed);
    const double x = v * t.washoutPerSpeed;
    local_ = {t.capacityRate,
              t.advectionPerSpeed * v,
              t.kernelScale,
              t.invStationaryG0,
              t.invMovingG0 / washout::firstStepFactor(x),
              washout::decay(x),
              washout::depositFactor(x)};
    localSpeed_ = slidingSpeed, localForce_ = bowForce;
    return local_;
}

// T[n] = (P + C T[n-1]/dt + H_s/g0_s + H_m/g0_m) / (C/dt + G_adv + 1/g0_s + 1/g0_m) ([Notes] eq. 2.9 with
// both solids; the layer is thin, so both surfaces under it share its temperature).
double HeatBalance::solveTemperature(double powerW, const Local& l) const noexcept
{
    return (powerW + l.capacityRate * temperature_ + stationary_.historySum() * l.invStationary +
            moving_.historySum() * l.invMoving) /
           (l.capacityRate + l.advection + l.invStationary + l.invMoving);
}

double HeatBalance::predict(double powerW, double slidingSpeed, double bowForce) const noexcept
{
    const double P = sanitiseNonNegative(powerW);
    if (atRest_ && P == 0.0)
        return 0.0; // what solveTemperature gives: no power, no stored heat
    return solveTemperature(P, local(slidingSpeed, bowForce));
}

void HeatBalance::commit(double powerW, double slidingSpeed, double bowForce) noexcept
{
    const double P = sanitiseNonNegative(powerW);
    if (atRest_ && P == 0.0)
        return; // the step would leave every value at exactly zero
    atRest_ = false;
    const Local& l = local(slidingSpeed, bowForce);
    const double T = solveTemperature(P, l);
    const double toStationary = (T - stationary_.historySum()) * l.invStationary; // W
    const double toMoving = (T - moving_.historySum()) * l.invMoving;             // W
    if (!std::isfinite(T) || !std::isfinite(toStationary) || !std::isfinite(toMoving))
    {
        reset();
        return;
    }
    // The flux deposited now keeps this step's area (kernel weights are per reference area).
    stationary_.advance(l.kernelScale * toStationary, 1.0);
    moving_.advance(l.kernelScale * toMoving * l.deposit, l.washout);
    temperature_ = T;
    stationaryFlux_ = toStationary;
    movingFlux_ = toMoving;
}

void HeatBalance::open() noexcept
{
    if (atRest_)
        return; // nothing stored, nothing to decay
    stationary_.advance(0.0, 1.0);
    moving_.advance(0.0, 1.0);
    temperature_ = stationary_.historySum();
    stationaryFlux_ = movingFlux_ = 0.0;
}

double HeatBalance::steadyConductance(double slidingSpeed, double bowForce) const noexcept
{
    const Local& l = local(slidingSpeed, bowForce);
    const double x = sanitiseNonNegative(slidingSpeed) * forceTerms(bowForce).washoutPerSpeed;
    const double Rs = l.kernelScale * stationary_.discreteSteadyResistance(1.0, 1.0, 1.0);
    const double Rm =
        l.kernelScale * moving_.discreteSteadyResistance(l.washout, l.deposit, washout::firstStepFactor(x));
    return l.advection + 1.0 / Rs + 1.0 / Rm;
}

double HeatBalance::steadyConductance(const ContactGeometry& geometry, const ContactMaterials& materials,
                                      double bowForce, double slidingSpeed) noexcept
{
    const double v = sanitiseNonNegative(slidingSpeed);
    const double a = geometry.radiusAt(clampForce(bowForce));
    const ThermalMaterial& s = materials.stationary;
    const ThermalMaterial& m = materials.moving;
    const double washoutTime = v > 0.0 ? washout::kLengthPerRadius * a / v : 0.0; // 0: never washed out
    return materials.layer.volumetricHeatCapacity * materials.advectionWidthRatio * a *
               geometry.layerThickness * v +
           1.0 / ConductionKernel::washedOutResistance(a, m.conductivity, m.volumetricHeatCapacity,
                                                       washoutTime) +
           1.0 / ConductionKernel::steadyResistance(a, s.conductivity);
}

} // namespace rosin::physics
