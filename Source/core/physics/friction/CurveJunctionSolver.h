#pragma once
// Exact intersection of the load line with a convex, decreasing friction curve, with the hysteresis rule
// that resolves Friedlander's ambiguity ([Notes §1.3.1-1.3.2]; [MSW1983]).
//
// For dvHistory > 0 a sliding solution x = |dv| in (0, dvHistory) solves
//     phi(x) = 2Z (x - dvHistory) + Fb mu(x) = 0.
// phi is convex (mu'' > 0), so it has no root, one root, or two roots; the smaller of two is the unstable
// middle intersection and is never chosen. The stick point (x = 0) is admissible when phi(0+) >= 0.
// Hysteresis rule: a sticking string stays stuck while it may; a sliding string stays on its (outer)
// sliding branch while that branch exists. A jump happens only when the followed branch vanishes.
#include <algorithm>
#include <cmath>
#include <utility>

#include "core/physics/friction/FrictionCurves.h"
#include "core/physics/friction/FrictionLaw.h"

namespace rosin::physics
{

/// State the hysteresis rule needs from the previous sample.
struct CurveJunctionMemory
{
    bool sticking = true;
    double previousDv = 0.0;
};

namespace detail
{
/// Root of a monotone function on [lo, hi] where sign(f(lo)) != sign(f(hi)); safeguarded Newton.
/// fdf(x) returns {f(x), f'(x)} together (one evaluation of the curve's exponentials per iteration).
template <typename FDF> double monotoneRoot(FDF fdf, double lo, double hi, double flo) noexcept
{
    double x = 0.5 * (lo + hi);
    for (int it = 0; it < 60; ++it)
    {
        const auto [fx, d] = fdf(x);
        if ((fx < 0.0) == (flo < 0.0))
            lo = x;
        else
            hi = x;
        double next = (d != 0.0) ? x - fx / d : 0.5 * (lo + hi);
        if (!(next > lo && next < hi))
            next = 0.5 * (lo + hi);
        if (std::abs(next - x) <= 1e-14 + 1e-12 * std::abs(x) || hi - lo <= 1e-15)
            return next;
        x = next;
    }
    return x;
}
} // namespace detail

/// Solve one sample of the junction for a friction curve `curve` (mu(x), slope(x), x = |dv| >= 0).
template <typename Curve>
JunctionSolution solveCurveJunction(const Curve& curve, const JunctionInput& in,
                                    CurveJunctionMemory& memory) noexcept
{
    const double twoZ = in.loadSlope;
    const double Fb = std::max(in.bowForce, 0.0);
    const double dvh = in.dvHistory;
    const double side = dvh >= 0.0 ? 1.0 : -1.0;
    const double target = std::abs(dvh);
    // phi and its derivatives from one evaluation of the curve.
    auto phiAndSlope = [&](double x)
    {
        const CurvePoint p = curve.at(x);
        return std::pair{twoZ * (x - target) + Fb * p.mu, twoZ + Fb * p.slope};
    };
    auto slopeAndCurvature = [&](double x)
    {
        const CurvePoint p = curve.at(x);
        return std::pair{twoZ + Fb * p.slope, Fb * p.curvature};
    };
    auto dphi = [&](double x) { return twoZ + Fb * curve.slope(x); };

    const double stickLimit = Fb * curve.staticMu();
    const bool stickAdmissible = twoZ * target <= stickLimit;
    JunctionSolution out;
    auto stick = [&]
    {
        out = {0.0, -twoZ * dvh, true};
        memory = {true, 0.0};
        return out;
    };
    auto slide = [&](double x)
    {
        out = {side * x, -side * Fb * curve.mu(x), false};
        memory = {false, out.dv};
        return out;
    };
    if (Fb <= 0.0 || target == 0.0)
        return Fb <= 0.0 ? slide(target) : stick();

    const double phi0 = twoZ * -target + stickLimit; // phi(0+)
    if (!stickAdmissible)
        return slide(detail::monotoneRoot(phiAndSlope, 0.0, target, phi0)); // exactly one root
    // Stick is admissible. Slip roots exist only if phi dips below zero at its minimum.
    const bool wasSlidingThisSide = !memory.sticking && memory.previousDv * side > 0.0;
    if (!wasSlidingThisSide || dphi(0.0) >= 0.0)
        return stick();
    // Minimum of phi: slope(x) = -2Z/Fb, found on [0, target] (dphi increasing).
    double xmin = target;
    if (dphi(target) > 0.0)
        xmin = detail::monotoneRoot(slopeAndCurvature, 0.0, target, dphi(0.0));
    const double phiMin = phiAndSlope(xmin).first;
    if (phiMin >= 0.0)
        return stick(); // the sliding branch has vanished past tangency: capture
    return slide(detail::monotoneRoot(phiAndSlope, xmin, target, phiMin)); // outer stable root
}

} // namespace rosin::physics
