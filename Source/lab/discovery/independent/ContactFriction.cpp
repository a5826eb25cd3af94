#include "lab/discovery/independent/ContactFriction.h"

#include <cmath>

namespace rosin::discovery
{

namespace
{
// The root of `residual` in [0, hi], where it is negative at 0 and positive at hi: the Illinois method
// [DowellJarratt1971].
template <class Residual> double bracketedRoot(const Residual& residual, double hi)
{
    double lo = 0.0;
    double rlo = residual(lo), rhi = residual(hi);
    int side = 0;
    for (int i = 0; i < 60 && hi - lo > 1e-13 * (1.0 + hi); ++i)
    {
        const double F = (lo * rhi - hi * rlo) / (rhi - rlo);
        const double r = residual(F);
        if ((r < 0.0) == (rlo < 0.0))
        {
            lo = F;
            rlo = r;
            if (side == -1)
                rhi *= 0.5; // Illinois: halve the stale end so the bracket keeps shrinking on both sides
            side = -1;
        }
        else
        {
            hi = F;
            rhi = r;
            if (side == 1)
                rlo *= 0.5;
            side = 1;
        }
        if (r == 0.0)
            lo = hi = F;
    }
    return 0.5 * (lo + hi);
}

FrictionSolution sliding(double dvh, double Y, double F)
{
    const double x = std::abs(dvh);
    const double sign = dvh > 0.0 ? -1.0 : 1.0;
    FrictionSolution s;
    s.force = sign * F;
    s.slip = -sign * (x - Y * F);
    s.power = F * (x - Y * F);
    s.sticking = false;
    return s;
}
} // namespace

ContactFriction::ContactFriction(const YieldStressTable& table, double area, double layer,
                                 const OwnEffects& effects, double dt)
    : table_(table), area_(area), layer_(layer), effects_(effects), dt_(dt)
{
}

double ContactFriction::plastic(double T) const noexcept
{
    return area_ * table_.at(T + effects_.ambientOffset);
}

double ContactFriction::staticLimit(double T) const noexcept
{
    double limit = plastic(T);
    if (effects_.growthGain > 0.0)
        limit *= 1.0 + effects_.growthGain * -std::expm1(-holdTime_ / effects_.growthTime);
    if (effects_.breakawayMargin > 0.0)
        limit *= 1.0 + effects_.breakawayMargin * std::exp(-std::max(T, 0.0) / effects_.breakawayWarmth);
    return limit;
}

FrictionSolution ContactFriction::solve(double dvh, double Y, const ContactHeat::Prediction& heat) noexcept
{
    if (effects_.viscous)
        return slideViscous(dvh, Y, heat);
    const double holding = std::abs(dvh) / Y; // force that keeps dv = 0
    const double limit = staticLimit(heat.free);
    const double sign = dvh > 0.0 ? -1.0 : 1.0; // friction opposes the history slip
    FrictionSolution s;
    if (holding <= limit)
    {
        s.force = sign * holding;
        const double threshold = effects_.creepShare * limit;
        if (effects_.creepResistance > 0.0 && holding > threshold)
        {
            // Bingham creep on the load line: F Y = |dv_h| - (F - threshold) / R.
            const double R = effects_.creepResistance;
            const double F = (std::abs(dvh) + threshold / R) / (Y + 1.0 / R);
            s.force = sign * F;
            s.slip = -sign * (F - threshold) / R;
            s.power = F * std::abs(s.slip);
        }
        holdTime_ += dt_;
        return s;
    }
    holdTime_ = 0.0;
    return slide(dvh, Y, heat);
}

FrictionSolution ContactFriction::slide(double dvh, double Y, const ContactHeat::Prediction& heat) const
{
    const double x = std::abs(dvh);
    auto residual = [&](double F) { return F - plastic(heat.at(F * (x - Y * F))); };
    return sliding(dvh, Y, bracketedRoot(residual, x / Y));
}

FrictionSolution ContactFriction::slideViscous(double dvh, double Y,
                                               const ContactHeat::Prediction& heat) const
{
    const double x = std::abs(dvh);
    const double c = area_ / layer_;
    auto residual = [&](double F)
    {
        const double slip = x - Y * F;
        return F - c * table_.viscosity(heat.at(F * slip) + effects_.ambientOffset) * slip;
    };
    FrictionSolution s = sliding(dvh, Y, bracketedRoot(residual, x / Y));
    s.sticking = std::abs(s.slip) < 1e-4; // a label for the trace only, as for a creeping contact
    return s;
}

} // namespace rosin::discovery
