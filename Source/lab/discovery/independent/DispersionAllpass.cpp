#include "lab/discovery/independent/DispersionAllpass.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rosin::discovery
{

namespace
{
// More, weaker sections follow the stiff string's delay curve further up: 128 hold every partial up to
// 10 kHz within 1 cent for the cello D at 88.2 kHz (96 sections: 3 cents; 24 sections fitted to 10 kHz:
// 10 cents). Fewer are used when they already fit within kGoodCents.
constexpr int kSectionChoices[] = {8, 16, 32, 64, 96, 128};
constexpr double kGoodCents = 0.3;

double sectionDelay(double a, double w)
{
    return 1.0 - 2.0 / w * std::atan2(a * std::sin(w), 1.0 + a * std::cos(w));
}

// Mean squared misfit (samples^2) of M sections of coefficient a to the needed delay differences.
double misfit(int m, double a, const std::vector<double>& w, const std::vector<double>& need)
{
    double e = 0.0;
    for (std::size_t k = 1; k < w.size(); ++k)
    {
        const double d = m * (sectionDelay(a, w[k]) - sectionDelay(a, w[0])) - need[k];
        e += d * d;
    }
    return e / static_cast<double>(std::max<std::size_t>(1, w.size() - 1));
}

// Golden section for the coefficient of m sections.
double bestCoefficient(int m, const std::vector<double>& w, const std::vector<double>& need)
{
    double lo = -0.95, hi = 0.0;
    for (int i = 0; i < 60; ++i)
    {
        const double c = hi - 0.618 * (hi - lo), d = lo + 0.618 * (hi - lo);
        if (misfit(m, c, w, need) < misfit(m, d, w, need))
            hi = d;
        else
            lo = c;
    }
    return 0.5 * (lo + hi);
}
} // namespace

DispersionDesign designDispersion(double loopSamples, double f0, double B, double sampleRate,
                                  const std::function<double(double)>& otherDelay, double fitTopHz)
{
    if (!(B > 0.0))
        return {};
    const double top = std::min(fitTopHz, 0.4 * sampleRate);
    std::vector<double> w, need;
    for (int n = 1; n * f0 * std::sqrt(1.0 + B * n * n) < top; ++n)
    {
        const double fn = n * f0 * std::sqrt(1.0 + B * n * n);
        w.push_back(2.0 * std::numbers::pi * fn / sampleRate);
        // The loop delay that puts mode n at fn, minus the fundamental's.
        double d = loopSamples * (1.0 / std::sqrt(1.0 + B * n * n) - 1.0 / std::sqrt(1.0 + B));
        if (otherDelay)
            d -= otherDelay(fn) - otherDelay(f0 * std::sqrt(1.0 + B));
        need.push_back(d);
    }
    // A delay error of d samples moves a partial by 1731 d / loop cents.
    const double good = kGoodCents * loopSamples / 1731.0;
    DispersionDesign best;
    double bestError = misfit(0, 0.0, w, need);
    for (int m : kSectionChoices)
    {
        const double a = bestCoefficient(m, w, need), e = misfit(m, a, w, need);
        if (e < bestError)
        {
            bestError = e;
            best = {a, m};
        }
        if (bestError < good * good)
            break;
    }
    return best;
}

DispersionAllpass::DispersionAllpass(const DispersionDesign& design, int sections, double sampleRate)
    : a_(design.coefficient), sampleRate_(sampleRate),
      state_(static_cast<std::size_t>(std::max(0, sections)), 0.0)
{
}

double DispersionAllpass::phaseDelay(double f) const noexcept
{
    if (state_.empty())
        return 0.0;
    return sections() * sectionDelay(a_, 2.0 * std::numbers::pi * f / sampleRate_);
}

} // namespace rosin::discovery
