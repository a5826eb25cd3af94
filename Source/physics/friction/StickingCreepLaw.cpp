#include "StickingCreepLaw.h"

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
    JunctionSolution s = inner_->solve(in);
    if (!s.sticking)
        return s;
    // Still "sticking" in the sense of the law (no slip has broken the contact), but creeping.
    s.dv = in.loadSlope * in.dvHistory / (in.loadSlope + eta_);
    s.frictionForce = -eta_ * s.dv;
    return s;
}

} // namespace rosin::physics
