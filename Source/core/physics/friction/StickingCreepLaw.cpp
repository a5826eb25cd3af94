#include "core/physics/friction/StickingCreepLaw.h"

#include <stdexcept>

namespace rosin::physics
{

StickingCreepLaw::StickingCreepLaw(std::unique_ptr<FrictionLaw> inner, double eta)
    : inner_(std::move(inner)), eta_(eta)
{
    if (!inner_)
        throw std::invalid_argument("StickingCreepLaw: no friction law to wrap");
    if (!(eta > 0.0))
        throw std::invalid_argument("StickingCreepLaw: creep resistance must be > 0 N s/m");
}

JunctionSolution StickingCreepLaw::solve(const JunctionInput& in) noexcept
{
    // Still "sticking" in the sense of the law (no slip has broken the contact), but creeping.
    return inner_->solveCreeping(in, eta_);
}

} // namespace rosin::physics
