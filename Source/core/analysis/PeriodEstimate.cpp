#include "core/analysis/PeriodEstimate.h"

#include <algorithm>
#include <cmath>

namespace rosin::analysis
{

namespace
{
// Normalised autocorrelation of the zero-mean stretch y at lag L (0 where either part is silent).
double correlationAt(const std::vector<double>& y, std::size_t lag)
{
    double sxy = 0.0, sxx = 0.0, syy = 0.0;
    for (std::size_t k = 0; k + lag < y.size(); ++k)
    {
        sxy += y[k] * y[k + lag];
        sxx += y[k] * y[k];
        syy += y[k + lag] * y[k + lag];
    }
    return sxx > 0.0 && syy > 0.0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

// The highest correlation at lags [lo, hi], refined by the parabola through it and its neighbours; nullopt
// on the edge of the range.
std::optional<double> peakLag(const std::vector<double>& y, std::size_t lo, std::size_t hi)
{
    std::vector<double> r(hi - lo + 1);
    for (std::size_t lag = lo; lag <= hi; ++lag)
        r[lag - lo] = correlationAt(y, lag);
    const auto best = static_cast<std::size_t>(std::max_element(r.begin(), r.end()) - r.begin());
    if (best == 0 || best + 1 == r.size())
        return std::nullopt;
    const double a = r[best - 1], b = r[best], c = r[best + 1];
    const double curvature = a - 2.0 * b + c;
    return static_cast<double>(lo + best) + (curvature < 0.0 ? 0.5 * (a - c) / curvature : 0.0);
}
} // namespace

std::optional<double> refinedPeriod(const std::vector<double>& x, std::size_t begin, std::size_t end,
                                    double roughPeriod, double searchShare)
{
    end = std::min(end, x.size());
    if (!(roughPeriod >= 4.0) || begin >= end || static_cast<double>(end - begin) < 3.0 * roughPeriod)
        return std::nullopt;
    std::vector<double> y(x.begin() + static_cast<std::ptrdiff_t>(begin),
                          x.begin() + static_cast<std::ptrdiff_t>(end));
    double mean = 0.0;
    for (double v : y)
        mean += v;
    mean /= static_cast<double>(y.size());
    for (double& v : y)
        v -= mean;
    const auto one = peakLag(y, static_cast<std::size_t>(std::floor(roughPeriod * (1.0 - searchShare))),
                             static_cast<std::size_t>(std::ceil(roughPeriod * (1.0 + searchShare))));
    if (!one)
        return std::nullopt;
    // The parabola through a correlation peak that is a cusp (a signal jumping once a period) is off by up to
    // ~0.07 sample; read at N periods (half the stretch) and divided by N, that error is N times smaller.
    const auto periods = static_cast<std::size_t>(static_cast<double>(y.size()) / (2.0 * *one));
    if (periods < 2)
        return one;
    const double centre = static_cast<double>(periods) * *one;
    const double reach = 0.1 * static_cast<double>(periods) + 2.0; // the first estimate's error, N times
    const auto many = peakLag(y, static_cast<std::size_t>(std::floor(centre - reach)),
                              static_cast<std::size_t>(std::ceil(centre + reach)));
    return many ? std::optional<double>(*many / static_cast<double>(periods)) : one;
}

} // namespace rosin::analysis
