#include "lab/discovery/independent/ContactFriction.h"

#include <cmath>

namespace rosin::discovery
{

ContactFriction::ContactFriction(const YieldStressTable& table, double area, const OwnEffects& effects,
                                 double dt)
    : table_(table), area_(area), effects_(effects), dt_(dt)
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
    double lo = 0.0, hi = x / Y;
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
    const double F = 0.5 * (lo + hi);
    const double sign = dvh > 0.0 ? -1.0 : 1.0;
    FrictionSolution s;
    s.force = sign * F;
    s.slip = -sign * (x - Y * F);
    s.power = F * (x - Y * F);
    s.sticking = false;
    return s;
}

} // namespace rosin::discovery
