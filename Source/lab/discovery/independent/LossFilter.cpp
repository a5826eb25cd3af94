#include "lab/discovery/independent/LossFilter.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace rosin::discovery
{

namespace
{
// The filter's response at normalised angular frequency w.
std::complex<double> response(double g, double p, double w)
{
    const std::complex<double> lowPass = (1.0 - p) / (1.0 - p * std::polar(1.0, -w));
    return 1.0 - g + g * lowPass;
}

// Attenuation -ln|H| at w.
double attenuation(double g, double p, double w)
{
    return -std::log(std::abs(response(g, p, w)));
}

// The share g (0..1) that gives attenuation a at w for pole p (attenuation grows with g), by bisection.
double shareFor(double p, double w, double a)
{
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 60; ++i)
    {
        const double mid = 0.5 * (lo + hi);
        (attenuation(mid, p, w) < a ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}
} // namespace

LossLaw stringLossLaw(double tension, double massPerLength, double bendingStiffness, double etaF, double etaB,
                      double etaA, double extraEta, double bendingFactor)
{
    return [=](double f)
    {
        const double w = 2.0 * std::numbers::pi * std::max(f, 1e-3);
        // Wavenumber of a free wave of the stiff string: P k^2 + EI k^4 = m w^2.
        const double k2 =
            bendingStiffness > 0.0
                ? (-tension + std::sqrt(tension * tension + 4.0 * bendingStiffness * massPerLength * w * w)) /
                      (2.0 * bendingStiffness)
                : massPerLength * w * w / tension;
        const double bend = bendingStiffness * k2;
        return (tension * (etaF + etaA / w) + bend * etaB * bendingFactor) / (tension + bend) + extraEta;
    };
}

OnePoleLoss::OnePoleLoss(const LossLaw& eta, double tau, double f1, double f2, double sampleRate)
    : sampleRate_(sampleRate)
{
    const double a1 = std::numbers::pi * eta(f1) * f1 * tau;
    const double a2 = std::numbers::pi * eta(f2) * f2 * tau;
    const double w1 = 2.0 * std::numbers::pi * f1 / sampleRate;
    const double w2 = 2.0 * std::numbers::pi * f2 / sampleRate;
    // For each pole, g makes the attenuation at f1 exact, which needs a pole at least as large as the one
    // that gives a1 with g = 1 (the plain one-pole); from there the ratio a(f2) / a(f1) falls from
    // ~(w2/w1)^2 towards 1 as p -> 1, so the pole that gives a2 at f2 follows by bisection.
    double lo = 0.0, hi = 0.9999;
    for (int i = 0; i < 60; ++i)
    {
        const double mid = 0.5 * (lo + hi);
        (attenuation(1.0, mid, w1) < a1 ? lo : hi) = mid;
    }
    lo = hi;
    hi = 0.9999;
    for (int i = 0; i < 60; ++i)
    {
        const double mid = 0.5 * (lo + hi);
        (attenuation(shareFor(mid, w1, a1), mid, w2) > a2 ? lo : hi) = mid;
    }
    pole_ = 0.5 * (lo + hi);
    gain_ = shareFor(pole_, w1, a1);
}

double OnePoleLoss::magnitude(double f) const noexcept
{
    return std::abs(response(gain_, pole_, 2.0 * std::numbers::pi * f / sampleRate_));
}

double OnePoleLoss::phaseDelay(double f) const noexcept
{
    const double w = 2.0 * std::numbers::pi * f / sampleRate_;
    return -std::arg(response(gain_, pole_, w)) / w;
}

} // namespace rosin::discovery
