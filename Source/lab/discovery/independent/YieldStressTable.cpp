#include "lab/discovery/independent/YieldStressTable.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rosin::discovery
{

namespace
{
constexpr double kMinSpeed = 1e-7, kMaxSpeed = 10.0; ///< m/s
constexpr int kPerDecade = 40;
constexpr double kColdSpan = 5.0; ///< K over which the cold slope is taken
constexpr double kColdCap = 0.25; ///< at most +25 % below ambient
} // namespace

double classicalFriction(double v)
{
    const double x = std::abs(v);
    return 0.4 * std::exp(-x / 0.01) + 0.45 * std::exp(-x / 0.1) + 0.35;
}

YieldStressTable::YieldStressTable(const CalibrationContact& rig, const HeatMaterials& materials, double dt)
{
    const ContactHeat heat(rig.radius, rig.layerThickness, materials, dt);
    const double area = std::numbers::pi * rig.radius * rig.radius;
    speeds_.push_back(0.0);
    temperatures_.push_back(0.0);
    stresses_.push_back(rig.normalForce * classicalFriction(0.0) / area);
    const int points = static_cast<int>(std::log10(kMaxSpeed / kMinSpeed) * kPerDecade);
    for (int i = 0; i <= points; ++i)
    {
        const double v = kMinSpeed * std::pow(10.0, static_cast<double>(i) / kPerDecade);
        const double mu = classicalFriction(v);
        const double T = rig.normalForce * mu * v * heat.steadyRise(v);
        if (T <= temperatures_.back())
            break;
        speeds_.push_back(v);
        temperatures_.push_back(T);
        stresses_.push_back(rig.normalForce * mu / area);
        logViscosities_.push_back(std::log(stresses_.back() * rig.layerThickness / v));
    }
    coldSlope_ = (stresses_.front() - at(kColdSpan)) / kColdSpan;
}

double YieldStressTable::at(double T) const noexcept
{
    if (T <= 0.0)
        return stresses_.front() + std::min(coldSlope_ * -T, kColdCap * stresses_.front());
    if (T >= temperatures_.back())
        return stresses_.back();
    const auto it = std::upper_bound(temperatures_.begin(), temperatures_.end(), T);
    const std::size_t i = static_cast<std::size_t>(it - temperatures_.begin());
    const double w = (T - temperatures_[i - 1]) / (temperatures_[i] - temperatures_[i - 1]);
    return stresses_[i - 1] + w * (stresses_[i] - stresses_[i - 1]);
}

double YieldStressTable::viscosity(double T) const noexcept
{
    if (T <= temperatures_[1])
        return std::exp(logViscosities_.front());
    if (T >= temperatures_.back())
        return std::exp(logViscosities_.back());
    const auto it = std::upper_bound(temperatures_.begin() + 1, temperatures_.end(), T);
    const std::size_t i = static_cast<std::size_t>(it - temperatures_.begin()); // 2 .. size - 1
    const double w = (T - temperatures_[i - 1]) / (temperatures_[i] - temperatures_[i - 1]);
    return std::exp(logViscosities_[i - 2] + w * (logViscosities_[i - 1] - logViscosities_[i - 2]));
}

} // namespace rosin::discovery
