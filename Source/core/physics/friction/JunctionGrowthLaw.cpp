#include "core/physics/friction/JunctionGrowthLaw.h"

#include <cmath>
#include <stdexcept>

namespace rosin::physics
{

JunctionGrowthLaw::JunctionGrowthLaw(std::unique_ptr<FrictionLaw> inner, double growth, double tauSeconds,
                                     AgeingForm form)
    : HeldContactLaw(std::move(inner), "JunctionGrowthLaw"), growth_(growth), tau_(tauSeconds), form_(form)
{
    if (!(growth >= 0.0) || !(tauSeconds > 0.0))
        throw std::invalid_argument("JunctionGrowthLaw: growth must be >= 0 and tau > 0 s");
}

double JunctionGrowthLaw::growthFactor() const noexcept
{
    const double x = holdTime() / tau_;
    return 1.0 + growth_ * (form_ == AgeingForm::Saturating ? -std::expm1(-x) : std::log1p(x));
}

} // namespace rosin::physics
