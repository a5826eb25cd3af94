#include "core/physics/bow/BowRibbon.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rosin::physics
{

double ribbonWidthOnString(double width, double beta, double length) noexcept
{
    return std::clamp(width, 0.0, 2.0 * beta * length);
}

double ribbonModeFactor(int n, double width, double length) noexcept
{
    const double x = 0.5 * n * std::numbers::pi * width / length;
    return x > 1e-12 ? std::sin(x) / x : 1.0;
}

double ribbonDirectShare(double waveSpeed, double samplePeriod, double width) noexcept
{
    if (!(width > 0.0))
        return 1.0;
    const double u = waveSpeed * samplePeriod / (2.0 * width);
    return u >= 1.0 ? 1.0 : u * (2.0 - u);
}

} // namespace rosin::physics
