#pragma once
// The one bracketed search of the physics: where a quantity is known to lie between two bounds, these narrow
// the bracket until it is small enough. Two forms for two kinds of question:
//  * bisectGeometric: a monotone yes/no test over a positive range spanning decades (a modal mass, a contact
//    radius), including tests whose answer is a step function (a stick-slip frequency counted in samples);
//  * illinoisRoot: a continuous residual with a sign change (the viscous law's temperature), by false
//  position
//    with the Illinois modification [DowellJarratt1971], which keeps the bracket and converges superlinearly.
// Header-only and allocation-free, so a friction law may call it per sample.
#include <cmath>

namespace rosin::physics
{

/// Bisects [lo, hi] (0 < lo < hi) at geometric midpoints: `below(x)` is true where x lies below the answer.
/// Stops when hi / lo <= 1 + ratioTolerance or after maxIterations halvings; returns sqrt(lo hi).
template <class Below>
double bisectGeometric(Below&& below, double lo, double hi, double ratioTolerance, int maxIterations)
{
    for (int it = 0; it < maxIterations && hi / lo > 1.0 + ratioTolerance; ++it)
    {
        const double mid = std::sqrt(lo * hi);
        (below(mid) ? lo : hi) = mid;
    }
    return std::sqrt(lo * hi);
}

/// When illinoisRoot stops: |g(x)| <= residual (1 + x), or the bracket hi - lo <= width (1 + hi) (x, hi >=
/// 0).
struct RootTolerance
{
    double residual = 1e-9;
    double width = 1e-12;
};

/// A root of `g` in the bracket [lo, hi] with glo = g(lo) > 0 > ghi = g(hi) (g decreasing through its root),
/// by Illinois false position; at most maxIterations evaluations of g. An endpoint with g = 0 is returned as
/// it is; `start` is returned when the bracket holds no sign change.
template <class G>
double illinoisRoot(G&& g, double lo, double glo, double hi, double ghi, double start,
                    RootTolerance tolerance, int maxIterations)
{
    int side = 0;
    double x = glo == 0.0 ? lo : ghi == 0.0 ? hi : start;
    for (int it = 0; it < maxIterations && glo > 0.0 && ghi < 0.0; ++it)
    {
        x = (lo * ghi - hi * glo) / (ghi - glo);
        const double gx = g(x);
        if (std::abs(gx) <= tolerance.residual * (1.0 + x) || hi - lo <= tolerance.width * (1.0 + hi))
            break;
        if (gx > 0.0)
        {
            lo = x, glo = gx;
            if (side == 1)
                ghi *= 0.5;
            side = 1;
        }
        else
        {
            hi = x, ghi = gx;
            if (side == -1)
                glo *= 0.5;
            side = -1;
        }
    }
    return x;
}

} // namespace rosin::physics
