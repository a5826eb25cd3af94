// Steady-sliding calibration of the thermal friction laws ([Notes §2.4], §3.2).
#include "core/physics/thermal/ThermalCalibration.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/physics/friction/FrictionCurves.h"
#include "core/physics/thermal/HeatBalance.h"

namespace rosin::physics
{

double ThermalCalibration::targetMu(CalibrationQuantity q, double v) noexcept
{
    const double x = std::abs(v);
    switch (q)
    {
    case CalibrationQuantity::YieldStress:
    case CalibrationQuantity::Viscosity:
        return ClassicalCurve{}.mu(x); // [Galluzzo2017] eq. 1 (= [Smith2000] eq. 2)
    case CalibrationQuantity::ModifiedBow:
    case CalibrationQuantity::ModifiedRod:
        return steadySlidingPowerLaw().mu(x); // [Woodhouse-thermal] eq. 11
    }
    return 0.0;
}

double ThermalCalibration::jumpCurve(CalibrationQuantity q, double v) noexcept
{
    const double x = std::abs(v);
    if (q == CalibrationQuantity::ModifiedBow)
        return bowJumpCurve().mu(x); // [Woodhouse-thermal] eq. 12
    if (q == CalibrationQuantity::ModifiedRod)
        return rodJumpCurve().mu(x); // [Woodhouse-thermal] eq. 13
    return 1.0;
}

void ThermalCalibration::build(const ContactParameters& contact, double sampleRate, CalibrationQuantity q)
{
    quantity_ = q;
    HeatBalance heat; // the heat model's own steady conductance, same time step as the law
    heat.prepare(contact.calibration, contact.materials, sampleRate);
    const double F = contact.calibration.referenceForce;
    const double a = contact.calibration.radiusAt(F);
    const double area = std::numbers::pi * a * a;
    const double delta = contact.calibration.layerThickness;

    auto value = [&](double v)
    {
        const double mu = targetMu(q, v);
        switch (q)
        {
        case CalibrationQuantity::YieldStress:
            return F * mu / area; // [Smith2000] eq. 4 with the calibration contact
        case CalibrationQuantity::Viscosity:
            return F * mu * delta / (area * v); // [Smith2000] eq. 3 solved for eta
        default:
            return mu / jumpCurve(q, v); // [Woodhouse-thermal] eq. 9 with K Y(T0) = 1 (eq. 8)
        }
    };

    speeds_.clear(), temperatures_.clear(), values_.clear(), logT_.clear(), logValue_.clear();
    truncated_ = false;
    const int n = static_cast<int>(std::lround(std::log10(kMaxSpeed / kMinSpeed) * kPointsPerDecade));
    for (int i = 0; i <= n; ++i)
    {
        const double v = kMinSpeed * std::pow(kMaxSpeed / kMinSpeed, double(i) / n);
        const double T = F * targetMu(q, v) * v / heat.steadyConductance(v, F); // steady map
        if (!temperatures_.empty() && !(T > temperatures_.back() * (1.0 + 1e-12)))
        {
            truncated_ = true; // T_ss has a maximum: keep the monotone (invertible) part only
            break;
        }
        speeds_.push_back(v);
        temperatures_.push_back(T);
        values_.push_back(value(v));
        logT_.push_back(std::log(T));
        logValue_.push_back(std::log(values_.back()));
    }
    // Ambient (v -> 0): finite for tau_y and K Y; eta diverges, so it is held at the first grid value.
    ambientValue_ = q == CalibrationQuantity::Viscosity ? values_.front() : value(0.0);
    constexpr int kUniformPoints = 8192;
    uniformIsLog_ = q == CalibrationQuantity::Viscosity;
    uniformStep_ = temperatures_.back() / (kUniformPoints - 1);
    uniform_.resize(kUniformPoints);
    for (int i = 0; i < kUniformPoints; ++i)
    {
        const double v = lookupLogLog(i * uniformStep_);
        uniform_[i] = uniformIsLog_ ? std::log(v) : v;
    }
}

double ThermalCalibration::lookup(double T) const noexcept
{
    if (uniform_.empty())
        return 0.0; // not built: no friction rather than undefined behaviour
    if (!(T > 0.0)) // also NaN
        return ambientValue_;
    const double x = T / uniformStep_;
    if (x < 1.0)
        return lookupLogLog(
            T); // the first cell, where the viscosity changes by decades, keeps the exact table
    if (x >= static_cast<double>(uniform_.size() - 1))
        return values_.back();
    const auto i = static_cast<std::size_t>(x);
    const double frac = x - static_cast<double>(i);
    const double y = uniform_[i] + frac * (uniform_[i + 1] - uniform_[i]);
    return uniformIsLog_ ? std::exp(y) : y;
}

double ThermalCalibration::lookupLogLog(double T) const noexcept
{
    if (temperatures_.empty())
        return 0.0; // not built: no friction rather than undefined behaviour
    if (!(T > 0.0)) // also NaN
        return ambientValue_;
    const double T0 = temperatures_.front();
    if (T <= T0)
        return ambientValue_ + (values_.front() - ambientValue_) * (T / T0);
    if (T >= temperatures_.back())
        return values_.back();
    const double x = std::log(T);
    const auto it = std::upper_bound(logT_.begin(), logT_.end(), x);
    const size_t i = static_cast<size_t>(it - logT_.begin()) - 1;
    const double frac = (x - logT_[i]) / (logT_[i + 1] - logT_[i]);
    return std::exp(logValue_[i] + frac * (logValue_[i + 1] - logValue_[i]));
}

} // namespace rosin::physics
