#include "core/physics/friction/HeldContactLaw.h"

#include <stdexcept>
#include <string>

namespace rosin::physics
{

HeldContactLaw::HeldContactLaw(std::unique_ptr<FrictionLaw> inner, const char* who) : inner_(std::move(inner))
{
    if (!inner_)
        throw std::invalid_argument(std::string(who) + ": no friction law to wrap");
}

void HeldContactLaw::prepare(double sampleRate)
{
    T_ = 1.0 / sampleRate;
    inner_->prepare(sampleRate);
    forget();
}

void HeldContactLaw::reset() noexcept
{
    inner_->reset();
    forget();
}

JunctionSolution HeldContactLaw::solve(const JunctionInput& in) noexcept
{
    return observed(inner_->solve(scaled(in)));
}

JunctionSolution HeldContactLaw::solveCreeping(const JunctionInput& in, double eta) noexcept
{
    return observed(inner_->solveCreeping(scaled(in), eta));
}

double HeldContactLaw::staticCoefficient(double bowForce) const noexcept
{
    const double g = forceFactor();
    return inner_->staticCoefficient(bowForce * g) * g;
}

JunctionInput HeldContactLaw::scaled(const JunctionInput& in) const noexcept
{
    JunctionInput s = in;
    s.bowForce = in.bowForce * forceFactor();
    return s;
}

JunctionSolution HeldContactLaw::observed(const JunctionSolution& s) noexcept
{
    observe(s);
    return s;
}

} // namespace rosin::physics
