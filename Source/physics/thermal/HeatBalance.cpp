// Implicit time marching of the contact heat balance (reference eqs. 2.4, 2.7, 2.9).
#include "HeatBalance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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

void HeatBalance::prepare(const ContactGeometry& geometry, const ThermalMaterial& material, double sampleRate)
{
    geometry_ = geometry;
    material_ = material;
    dt_ = 1.0 / sampleRate;
    effusivity_ = std::sqrt(material.conductivity * material.volumetricHeatCapacity);
    kernel_.fit(geometry.radius, material.conductivity, material.volumetricHeatCapacity, dt_);
    const auto& c = kernel_.coefficients();
    const auto& tau = kernel_.timeConstants();
    const size_t M = c.size();
    decay_.resize(M);
    weight_.resize(M);
    history_.assign(M, 0.0);
    for (size_t m = 0; m < M; ++m)
    {
        decay_[m] = std::exp(-dt_ / tau[m]);
        weight_[m] = c[m] * tau[m] * (1.0 - decay_[m]); // int over one step of c e^{-t/tau}, per unit flux
    }
    g0_ = kernel_.firstStepWeight();
    forceTerms_ = {}; // new geometry, material or time step
    stationaryResistance_ = kernel_.discreteSteadyResistance();
    reset();
}

void HeatBalance::reset() noexcept
{
    std::fill(history_.begin(), history_.end(), 0.0);
    temperature_ = 0.0;
    historySum_ = 0.0;
    lastFlux_ = 0.0;
}

const HeatBalance::ForceTerms& HeatBalance::forceTerms(double bowForce) const noexcept
{
    const double F = clampForce(bowForce);
    if (F == forceTerms_.force)
        return forceTerms_;
    const double a = geometry_.radiusAt(F);
    const double area = std::numbers::pi * a * a;
    const double rhoC = material_.volumetricHeatCapacity;
    const double delta = geometry_.layerThickness;
    ForceTerms& t = forceTerms_;
    t.force = F;
    t.capacityRate = rhoC * area * delta / dt_;
    t.advectionPerSpeed = rhoC * material_.advectionWidthRatio * a * delta;
    t.movingPerRootSpeed = area * effusivity_ * std::sqrt(3.0 / (8.0 * a));
    t.kernelScale = (geometry_.radius * geometry_.radius) / (a * a); // A_ref / A
    t.invScaledG0 = 1.0 / (t.kernelScale * g0_);
    return t;
}

HeatBalance::Local HeatBalance::local(double slidingSpeed, double bowForce) const noexcept
{
    const double v = sanitiseNonNegative(slidingSpeed);
    const ForceTerms& t = forceTerms(bowForce);
    // G_loc = advection (rho c w delta v) + moving-side conduction (pi a^2 e sqrt(3 v / (8 a))).
    return {t.capacityRate, t.advectionPerSpeed * v + t.movingPerRootSpeed * std::sqrt(v), t.kernelScale,
            t.invScaledG0};
}

// T[n] = (P + C T[n-1]/dt + H/g0) / (C/dt + G_loc + 1/g0), with g0 scaled by A_ref/A (reference eq. 2.9).
double HeatBalance::solveTemperature(double powerW, const Local& l) const noexcept
{
    return (powerW + l.capacityRate * temperature_ + historySum_ * l.invScaledG0) /
           (l.capacityRate + l.conductance + l.invScaledG0);
}

double HeatBalance::predict(double powerW, double slidingSpeed, double bowForce) const noexcept
{
    return solveTemperature(sanitiseNonNegative(powerW), local(slidingSpeed, bowForce));
}

void HeatBalance::commit(double powerW, double slidingSpeed, double bowForce) noexcept
{
    const Local l = local(slidingSpeed, bowForce);
    const double T = solveTemperature(sanitiseNonNegative(powerW), l);
    const double flux = (T - historySum_) * l.invScaledG0; // Q[n] into the stationary side, W
    if (!std::isfinite(T) || !std::isfinite(flux))
    {
        reset();
        return;
    }
    // u_m[n+1] = r_m (u_m[n] + c_m tau_m (1 - r_m) Q[n]); the flux deposited now keeps this step's area.
    const double scaledFlux = l.kernelScale * flux;
    double sum = 0.0;
    double* __restrict h = history_.data();
    const double* __restrict r = decay_.data();
    const double* __restrict w = weight_.data();
    const int M = static_cast<int>(history_.size());
#pragma omp simd reduction(+ : sum)
    for (int m = 0; m < M; ++m)
    {
        double u = r[m] * (h[m] + w[m] * scaledFlux);
        u = std::abs(u) < 1e-250 ? 0.0 : u; // keep long silences free of denormals
        h[m] = u;
        sum += u;
    }
    historySum_ = sum;
    temperature_ = T;
    lastFlux_ = flux;
}

double HeatBalance::steadyConductance(double slidingSpeed, double bowForce) const noexcept
{
    const Local l = local(slidingSpeed, bowForce);
    return l.conductance + 1.0 / (l.kernelScale * stationaryResistance_);
}

double HeatBalance::steadyConductance(const ContactGeometry& geometry, const ThermalMaterial& material,
                                      double bowForce, double slidingSpeed) noexcept
{
    const double v = sanitiseNonNegative(slidingSpeed);
    const double a = geometry.radiusAt(clampForce(bowForce));
    const double rhoC = material.volumetricHeatCapacity;
    const double e = std::sqrt(material.conductivity * rhoC);
    return rhoC * material.advectionWidthRatio * a * geometry.layerThickness * v +
           std::numbers::pi * a * a * e * std::sqrt(3.0 * v / (8.0 * a)) +
           1.0 / StationaryKernel::steadyResistance(a, material.conductivity);
}

} // namespace rosin::physics
