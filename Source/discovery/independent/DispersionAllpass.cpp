#include "DispersionAllpass.h"

#include <cmath>
#include <numbers>

namespace rosin::discovery
{

namespace
{
constexpr int kMaxSections = 24;
constexpr double kFitTopHz = 4000.0;

double sectionDelay(double a, double w)
{
    return 1.0 - 2.0 / w * std::atan2(a * std::sin(w), 1.0 + a * std::cos(w));
}

// Squared misfit of M sections of coefficient a to the needed delay differences.
double misfit(int m, double a, const std::vector<double>& w, const std::vector<double>& need)
{
    double e = 0.0;
    for (std::size_t k = 1; k < w.size(); ++k)
    {
        const double d = m * (sectionDelay(a, w[k]) - sectionDelay(a, w[0])) - need[k];
        e += d * d;
    }
    return e;
}
} // namespace

DispersionAllpass::DispersionAllpass(double loopSamples, double f0, double B, double sampleRate)
    : sampleRate_(sampleRate)
{
    if (!(B > 0.0))
        return;
    std::vector<double> w, need;
    for (int n = 1; n * f0 * std::sqrt(1.0 + B * n * n) < kFitTopHz; ++n)
    {
        const double fn = n * f0 * std::sqrt(1.0 + B * n * n);
        w.push_back(2.0 * std::numbers::pi * fn / sampleRate);
        // The loop delay that puts mode n at fn, minus the fundamental's.
        need.push_back(loopSamples * (1.0 / std::sqrt(1.0 + B * n * n) - 1.0 / std::sqrt(1.0 + B)));
    }
    double best = misfit(0, 0.0, w, need);
    int bestM = 0;
    for (int m = 1; m <= kMaxSections; ++m)
    {
        double lo = -0.95, hi = 0.0; // golden section on a for this m
        for (int i = 0; i < 60; ++i)
        {
            const double c = hi - 0.618 * (hi - lo), d = lo + 0.618 * (hi - lo);
            if (misfit(m, c, w, need) < misfit(m, d, w, need))
                hi = d;
            else
                lo = c;
        }
        const double a = 0.5 * (lo + hi), e = misfit(m, a, w, need);
        if (e < best)
        {
            best = e;
            bestM = m;
            a_ = a;
        }
    }
    state_.assign(static_cast<std::size_t>(bestM), 0.0);
}

double DispersionAllpass::phaseDelay(double f) const noexcept
{
    if (state_.empty())
        return 0.0;
    return sections() * sectionDelay(a_, 2.0 * std::numbers::pi * f / sampleRate_);
}

} // namespace rosin::discovery
