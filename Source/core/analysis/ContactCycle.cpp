#include "core/analysis/ContactCycle.h"

#include <algorithm>
#include <cmath>

namespace rosin::analysis
{

namespace
{
constexpr double kSlipThreshold = 0.5; ///< |dv| above this share of |v_b| is slipping

std::size_t clampedEnd(std::size_t to, const std::vector<double>& a, const std::vector<double>& b)
{
    return std::min({to, a.size(), b.size()});
}
} // namespace

std::optional<double> slipFraction(const std::vector<double>& bowPointVelocity,
                                   const std::vector<double>& bowVelocity, std::size_t from, std::size_t to)
{
    to = clampedEnd(to, bowPointVelocity, bowVelocity);
    if (from >= to)
        return std::nullopt;
    std::size_t slipping = 0, moving = 0;
    for (std::size_t k = from; k < to; ++k)
    {
        const double vb = std::abs(bowVelocity[k]);
        if (vb <= 0.0)
            continue;
        ++moving;
        slipping += std::abs(bowPointVelocity[k] - bowVelocity[k]) > kSlipThreshold * vb ? 1 : 0;
    }
    if (moving == 0)
        return std::nullopt;
    return static_cast<double>(slipping) / static_cast<double>(moving);
}

std::optional<double> normalisedLoopArea(const std::vector<double>& bowPointVelocity,
                                         const std::vector<double>& bowVelocity,
                                         const std::vector<double>& frictionForce, double bowForce,
                                         std::size_t from, std::size_t to, double periodSamples)
{
    to = std::min(clampedEnd(to, bowPointVelocity, bowVelocity), frictionForce.size());
    if (!(bowForce > 0.0) || !(periodSamples > 0.0) || to <= from ||
        static_cast<double>(to - from) < 2.0 * periodSamples)
        return std::nullopt;
    // Friction opposes sliding: orient f so that f (v - v_b) <= 0 on average while slipping.
    double power = 0.0, speed = 0.0;
    for (std::size_t k = from; k < to; ++k)
    {
        power += frictionForce[k] * (bowPointVelocity[k] - bowVelocity[k]);
        speed += std::abs(bowVelocity[k]);
    }
    if (!(speed > 0.0))
        return std::nullopt;
    const double sign = power > 0.0 ? -1.0 : 1.0;
    double twice = 0.0;
    for (std::size_t k = from; k + 1 < to; ++k)
    {
        const double x0 = bowPointVelocity[k] - bowVelocity[k],
                     x1 = bowPointVelocity[k + 1] - bowVelocity[k + 1];
        const double y0 = sign * frictionForce[k] / bowForce, y1 = sign * frictionForce[k + 1] / bowForce;
        twice += x0 * y1 - x1 * y0;
    }
    const double periods = static_cast<double>(to - from) / periodSamples;
    const double meanSpeed = speed / static_cast<double>(to - from);
    return 0.5 * twice / periods / meanSpeed;
}

} // namespace rosin::analysis
