#pragma once
// Friction coefficient as a function of sliding speed alone ("friction-curve" models). Each curve is
// convex and decreasing in |dv|, which the junction solver relies on (at most two slip roots).
// Each provides mu(x), slope(x) = dmu/dx and curvature(x) = d2mu/dx2 for x = |dv| >= 0.
#include <cmath>

namespace rosin::physics
{

/// A friction curve and its first two derivatives at one sliding speed.
struct CurvePoint
{
    double mu = 0.0;        ///< friction coefficient
    double slope = 0.0;     ///< dmu/dx, s/m
    double curvature = 0.0; ///< d2mu/dx2, s^2/m^2
};

/// Classical steady-sliding fit of Smith & Woodhouse ([Galluzzo2017] eq. 1; [Smith2000] eq. 2):
/// mu(x) = 0.4 exp(-x/0.01) + 0.45 exp(-x/0.1) + 0.35, x = |v - v_b| in m/s. mu_s = 1.2, mu(inf) = 0.35.
struct ClassicalCurve
{
    double mu(double x) const noexcept
    {
        return 0.4 * std::exp(-x / 0.01) + 0.45 * std::exp(-x / 0.1) + 0.35;
    }
    double slope(double x) const noexcept { return -40.0 * std::exp(-x / 0.01) - 4.5 * std::exp(-x / 0.1); }
    double curvature(double x) const noexcept
    {
        return 4000.0 * std::exp(-x / 0.01) + 45.0 * std::exp(-x / 0.1);
    }
    double staticMu() const noexcept { return 1.2; }
    CurvePoint at(double x) const noexcept
    {
        const double e1 = std::exp(-x / 0.01), e2 = std::exp(-x / 0.1);
        return {0.4 * e1 + 0.45 * e2 + 0.35, -40.0 * e1 - 4.5 * e2, 4000.0 * e1 + 45.0 * e2};
    }
};

/// Galluzzo's curve reconstructed from first-slip jumps ([Galluzzo2017] eq. 2):
/// mu(x) = 0.4 exp(-x/0.7) + 0.35. mu_s = 0.75.
struct ReconstructedCurve
{
    double mu(double x) const noexcept { return 0.4 * std::exp(-x / 0.7) + 0.35; }
    double slope(double x) const noexcept { return -0.4 / 0.7 * std::exp(-x / 0.7); }
    double curvature(double x) const noexcept { return 0.4 / 0.49 * std::exp(-x / 0.7); }
    double staticMu() const noexcept { return 0.75; }
    CurvePoint at(double x) const noexcept
    {
        const double e = std::exp(-x / 0.7);
        return {0.4 * e + 0.35, -0.4 / 0.7 * e, 0.4 / 0.49 * e};
    }
};

/// Power-law curve c (x + x0)^(-0.4) ([Woodhouse-thermal] eqs. 11-13): the revised steady-sliding fit
/// (c = 0.2, x0 = 0.011), the jump curve h(v) of a real bow (0.5, 0.27, eq. 12) or of a rosin-coated
/// rod (0.37, 0.35, eq. 13). Multiplied by `scale` (the modified law's K Y(T)).
struct PowerLawCurve
{
    double c = 0.2;
    double x0 = 0.011;
    double scale = 1.0;
    double mu(double x) const noexcept { return scale * c * std::pow(x + x0, -0.4); }
    double slope(double x) const noexcept { return -0.4 * scale * c * std::pow(x + x0, -1.4); }
    double curvature(double x) const noexcept { return 0.56 * scale * c * std::pow(x + x0, -2.4); }
    double staticMu() const noexcept { return mu(0.0); }
    CurvePoint at(double x) const noexcept
    {
        const double m = scale * c * std::pow(x + x0, -0.4), r = 1.0 / (x + x0);
        return {m, -0.4 * m * r, 0.56 * m * r * r};
    }
};

inline PowerLawCurve steadySlidingPowerLaw()
{
    return {0.2, 0.011, 1.0};
}
inline PowerLawCurve bowJumpCurve()
{
    return {0.5, 0.27, 1.0};
}
inline PowerLawCurve rodJumpCurve()
{
    return {0.37, 0.35, 1.0};
}

} // namespace rosin::physics
