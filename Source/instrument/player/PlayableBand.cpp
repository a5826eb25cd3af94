#include "instrument/player/PlayableBand.h"

#include <algorithm>
#include <cmath>

#include "core/physics/laws/GuettlerWedge.h"

namespace rosin::player
{

bool PlayableBand::valid() const noexcept
{
    return Z0 > 0.0 && std::isfinite(Z0) && conductance >= 0.0 && std::isfinite(conductance) &&
           muDynamic >= 0.0 && muStatic > muDynamic && std::isfinite(muStatic);
}

double PlayableBand::maximumForce(double bowSpeed, double beta) const noexcept
{
    return 2.0 * Z0 * std::abs(bowSpeed) / (beta * deltaMu());
}

double PlayableBand::minimumForce(double bowSpeed, double beta) const noexcept
{
    return Z0 * Z0 * std::abs(bowSpeed) * conductance / (2.0 * beta * beta * deltaMu());
}

double PlayableBand::placedForce(double bowSpeed, double beta, double placement) const noexcept
{
    const double high = upperEdge * maximumForce(bowSpeed, beta);
    // A lossless string has no lower limit; keep the log scale finite three decades below F_max.
    const double low = std::max(lowerEdge * minimumForce(bowSpeed, beta), 1e-3 * high);
    if (!(low < high))
        return std::sqrt(low * high);
    return low * std::pow(high / low, placement);
}

double PlayableBand::attackAccelerationPerNewton(double beta, double finger, double w) const noexcept
{
    const double pz0 = periodTimesZ0 * finger;
    if (!valid() || !(pz0 > 0.0) || !(beta > 0.0 && beta < 0.5))
        return 0.0;
    const physics::GuettlerWedge wedge = physics::guettlerWedge(beta, muStatic, muDynamic, pz0);
    const double lower = wedge.lowerAccelerationPerNewton, upper = wedge.upperAccelerationPerNewton;
    return lower > 0.0 && upper > lower ? lower * std::pow(upper / lower, w)
                                        : std::max(0.0, 0.5 * (lower + upper));
}

} // namespace rosin::player
