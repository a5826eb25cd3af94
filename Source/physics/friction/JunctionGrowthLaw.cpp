#include "JunctionGrowthLaw.h"

#include <cmath>
#include <stdexcept>

namespace rosin::physics
{

JunctionGrowthLaw::JunctionGrowthLaw(std::unique_ptr<FrictionLaw> inner, double growth, double tauSeconds,
                                     AgeingForm form)
    : inner_(std::move(inner)), growth_(growth), tau_(tauSeconds), form_(form)
{
    if (!inner_)
        throw std::invalid_argument("JunctionGrowthLaw: no friction law to wrap");
    if (!(growth >= 0.0) || !(tauSeconds > 0.0))
        throw std::invalid_argument("JunctionGrowthLaw: growth must be >= 0 and tau > 0 s");
}

void JunctionGrowthLaw::prepare(double sampleRate)
{
    T_ = 1.0 / sampleRate;
    inner_->prepare(sampleRate);
    holdSamples_ = 0;
}

void JunctionGrowthLaw::reset() noexcept
{
    inner_->reset();
    holdSamples_ = 0;
}

double JunctionGrowthLaw::growthFactor() const noexcept
{
    const double x = holdTime() / tau_;
    return 1.0 + growth_ * (form_ == AgeingForm::Saturating ? -std::expm1(-x) : std::log1p(x));
}

JunctionSolution JunctionGrowthLaw::solve(const JunctionInput& in) noexcept
{
    return counted(inner_->solve(aged(in)));
}

JunctionSolution JunctionGrowthLaw::solveCreeping(const JunctionInput& in, double eta) noexcept
{
    return counted(inner_->solveCreeping(aged(in), eta));
}

JunctionInput JunctionGrowthLaw::aged(const JunctionInput& in) const noexcept
{
    JunctionInput a = in;
    a.bowForce = in.bowForce * growthFactor();
    return a;
}

JunctionSolution JunctionGrowthLaw::counted(const JunctionSolution& s) noexcept
{
    // The hold time counts samples stuck so far (creeping included); a sliding sample breaks the junctions.
    holdSamples_ = s.sticking ? holdSamples_ + 1 : 0;
    return s;
}

double JunctionGrowthLaw::staticCoefficient(double bowForce) const noexcept
{
    const double g = growthFactor();
    return inner_->staticCoefficient(bowForce * g) * g;
}

} // namespace rosin::physics
