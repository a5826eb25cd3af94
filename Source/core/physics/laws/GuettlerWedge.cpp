#include "core/physics/laws/GuettlerWedge.h"

#include <cmath>

namespace rosin::physics
{

GuettlerWedge guettlerWedge(double beta, double ms, double md, double PZ0) noexcept
{
    const double scale = beta * (1.0 - beta) / PZ0;
    GuettlerWedge w;
    w.beta = beta;
    w.lowerAccelerationPerNewton = scale * (3.0 * ms - md - 2.0 * std::sqrt(2.0 * ms * ms - ms * md));
    w.upperAccelerationPerNewton =
        scale *
        ((3.0 - 4.0 * beta) * ms - md -
         2.0 * std::sqrt((1.0 - 2.0 * beta) * (2.0 * (1.0 - beta) * ms * ms - ms * md))) /
        (1.0 - 2.0 * beta);
    return w;
}

} // namespace rosin::physics
