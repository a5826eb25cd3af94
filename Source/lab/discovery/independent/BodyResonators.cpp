#include "lab/discovery/independent/BodyResonators.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rosin::discovery
{

BodyResonators::BodyResonators(const physics::BodyParameters& body, double sampleRate)
{
    const double T = 1.0 / sampleRate;
    for (const auto& m : body.modes)
    {
        if (m.frequency <= 0.0 || m.frequency >= 0.45 * sampleRate || m.effectiveMass <= 0.0)
            continue;
        const double w = 2.0 * std::numbers::pi * m.frequency;
        const double s = w / (2.0 * m.q);
        const double wd = w * std::sqrt(std::max(1e-12, 1.0 - 1.0 / (4.0 * m.q * m.q)));
        const double r = std::exp(-s * T);
        const double a1 = -2.0 * r * std::cos(wd * T), a2 = r * r;
        // T sum h(nT) z^-n = (T/m) (1 - r (cos + (s/wd) sin) z^-1) / (1 + a1 z^-1 + a2 z^-2).
        const double g = T / m.effectiveMass;
        const double c1 = -r * (std::cos(wd * T) + (s / wd) * std::sin(wd * T));
        // Minus the half weight at t = 0, over the same denominator.
        const double h = 0.5 * g;
        modes_.push_back({g - h, g * c1 - h * a1, -h * a2, a1, a2});
        y0_ += g - h;
    }
}

double BodyResonators::historyVelocity() const noexcept
{
    double v = 0.0;
    for (const auto& m : modes_)
        v += m.z1;
    return v;
}

void BodyResonators::advance(double force) noexcept
{
    for (auto& m : modes_)
    {
        const double y = m.b0 * force + m.z1;
        m.z1 = m.b1 * force - m.a1 * y + m.z2;
        m.z2 = m.b2 * force - m.a2 * y;
    }
}

void BodyResonators::reset() noexcept
{
    for (auto& m : modes_)
        m.z1 = m.z2 = 0.0;
}

} // namespace rosin::discovery
