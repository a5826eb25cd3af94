#include "instrument/player/DynamicsPath.h"

#include <algorithm>
#include <cmath>

#include "instrument/player/GestureParameters.h"

namespace rosin::player
{

namespace
{
double logPath(double from, double to, double d) noexcept
{
    return from * std::pow(to / from, std::clamp(d, 0.0, 1.0));
}
} // namespace

double DynamicsPath::bowSpeed(double dynamics) const noexcept
{
    return logPath(speedPp, speedFf, dynamics);
}

double DynamicsPath::beta(double dynamics) const noexcept
{
    return logPath(betaPp, betaFf, dynamics);
}

double DynamicsPath::placement(double bowPressure, double dynamics) const noexcept
{
    const double q = std::clamp(bowPressure, 0.0, 1.0);
    const double normal = normalPp + (normalFf - normalPp) * std::clamp(dynamics, 0.0, 1.0);
    return q <= 0.5 ? flautando + (normal - flautando) * 2.0 * q
                    : normal + (scratch - normal) * (2.0 * q - 1.0);
}

MusicalBow musicalBow(const DynamicsPath& path, const PlayableBand& band, double dynamics, double bowPressure,
                      double betaFactor) noexcept
{
    MusicalBow bow;
    bow.bowSpeed = std::clamp(path.bowSpeed(dynamics), ranges::bowSpeed.min, ranges::bowSpeed.max);
    bow.beta = std::clamp(path.beta(dynamics) * betaFactor, ranges::beta.min, ranges::beta.max);
    const PlayableBand used = band.valid() ? band : PlayableBand{0.5, 0.0, 1.2, 0.35};
    bow.bowForce = std::clamp(used.placedForce(bow.bowSpeed, bow.beta, path.placement(bowPressure, dynamics)),
                              kMusicalForceMin, kMusicalForceMax);
    bow.upperForce = used.upperEdge * used.maximumForce(bow.bowSpeed, bow.beta);
    return bow;
}

} // namespace rosin::player
