#include "LossFilter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rosin::discovery
{

namespace
{
// Attenuation -ln|H| of the one-pole (without its gain) at normalised angular frequency w: it is zero at DC
// and grows with w and with the pole p, so p follows from the difference of two targets by bisection.
double shape(double p, double w)
{
    return 0.5 * std::log(1.0 - 2.0 * p * std::cos(w) + p * p) - std::log(1.0 - p);
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
    const double target = std::max(0.0, a2 - a1);
    double lo = 0.0, hi = 0.999;
    for (int i = 0; i < 60; ++i)
    {
        const double mid = 0.5 * (lo + hi);
        (shape(mid, w2) - shape(mid, w1) < target ? lo : hi) = mid;
    }
    pole_ = 0.5 * (lo + hi);
    // The DC gain makes the attenuation at f1 exact; it may not exceed 1 (a passive string).
    gain_ = std::min(1.0, std::exp(shape(pole_, w1) - a1));
}

double OnePoleLoss::magnitude(double f) const noexcept
{
    const double w = 2.0 * std::numbers::pi * f / sampleRate_;
    return gain_ * std::exp(-shape(pole_, w));
}

double OnePoleLoss::phaseDelay(double f) const noexcept
{
    const double w = 2.0 * std::numbers::pi * f / sampleRate_;
    return std::atan2(pole_ * std::sin(w), 1.0 - pole_ * std::cos(w)) / w;
}

} // namespace rosin::discovery
