#include "StickingCreepLaw.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rosin::physics
{

StickingCreepLaw::StickingCreepLaw(std::unique_ptr<FrictionLaw> inner, double eta, double thresholdShare)
    : inner_(std::move(inner)), eta_(eta), share_(thresholdShare)
{
    if (!inner_)
        throw std::invalid_argument("StickingCreepLaw: no friction law to wrap");
    if (!(eta > 0.0))
        throw std::invalid_argument("StickingCreepLaw: creep resistance must be > 0 N s/m");
    if (!(thresholdShare >= 0.0 && thresholdShare < 1.0))
        throw std::invalid_argument("StickingCreepLaw: the threshold share must be in [0, 1)");
}

JunctionSolution StickingCreepLaw::solve(const JunctionInput& in) noexcept
{
    JunctionSolution s = inner_->solve(in);
    if (!s.sticking)
        return s;
    // Still "sticking" in the sense of the law (no slip has broken the contact), but creeping once the force
    // the contact must carry, 2Z |dvh|, exceeds the threshold.
    if (share_ == 0.0)
    {
        s.dv = in.loadSlope * in.dvHistory / (in.loadSlope + eta_);
        s.frictionForce = -eta_ * s.dv;
        return s;
    }
    const double threshold = share_ * inner_->staticCoefficient(in.bowForce) * in.bowForce;
    const double excess = std::max(0.0, in.loadSlope * std::abs(in.dvHistory) - threshold);
    s.dv = std::copysign(excess / (in.loadSlope + eta_), in.dvHistory);
    s.frictionForce = in.loadSlope * (s.dv - in.dvHistory);
    return s;
}

} // namespace rosin::physics
