#include "BreakawayMarginLaw.h"

#include <stdexcept>

namespace rosin::physics
{

BreakawayMarginLaw::BreakawayMarginLaw(std::unique_ptr<FrictionLaw> inner, double margin)
    : inner_(std::move(inner)), margin_(margin)
{
    if (!inner_)
        throw std::invalid_argument("BreakawayMarginLaw: no friction law to wrap");
    if (!(margin >= 0.0))
        throw std::invalid_argument("BreakawayMarginLaw: margin must be >= 0");
}

void BreakawayMarginLaw::prepare(double sampleRate)
{
    inner_->prepare(sampleRate);
    released_ = false;
}

void BreakawayMarginLaw::reset() noexcept
{
    inner_->reset();
    released_ = false;
}

JunctionSolution BreakawayMarginLaw::solve(const JunctionInput& in) noexcept
{
    return watched(inner_->solve(held(in)));
}

JunctionSolution BreakawayMarginLaw::solveCreeping(const JunctionInput& in, double eta) noexcept
{
    return watched(inner_->solveCreeping(held(in), eta));
}

JunctionInput BreakawayMarginLaw::held(const JunctionInput& in) const noexcept
{
    JunctionInput h = in;
    h.bowForce = in.bowForce * factor();
    return h;
}

JunctionSolution BreakawayMarginLaw::watched(const JunctionSolution& s) noexcept
{
    released_ = released_ || !s.sticking; // creeping counts as held: the junctions have not broken
    return s;
}

double BreakawayMarginLaw::staticCoefficient(double bowForce) const noexcept
{
    const double g = factor();
    return inner_->staticCoefficient(bowForce * g) * g;
}

std::optional<double> BreakawayMarginLaw::restingLimit(double bowForce) const noexcept
{
    if (released_)
        return inner_->restingLimit(bowForce);
    return inner_->restingLimit(bowForce * (1.0 + margin_));
}

} // namespace rosin::physics
