#include "core/physics/friction/BreakawayMarginLaw.h"

#include <stdexcept>

namespace rosin::physics
{

BreakawayMarginLaw::BreakawayMarginLaw(std::unique_ptr<FrictionLaw> inner, double margin)
    : HeldContactLaw(std::move(inner), "BreakawayMarginLaw"), margin_(margin)
{
    if (!(margin >= 0.0))
        throw std::invalid_argument("BreakawayMarginLaw: margin must be >= 0");
}

std::optional<double> BreakawayMarginLaw::restingLimit(double bowForce) const noexcept
{
    return inner().restingLimit(bowForce * forceFactor());
}

} // namespace rosin::physics
