#include "core/physics/body/BodyRadiation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rosin::physics
{
namespace
{
constexpr double kTwoPi = 2.0 * std::numbers::pi;
} // namespace

double statisticalRadiationEfficiency(const BodyRadiation& radiation, double frequencyHz) noexcept
{
    return std::clamp(frequencyHz / radiation.unityEfficiencyHz, 0.0, 1.0);
}

double directivity(const BodyRadiation& radiation, double frequencyHz) noexcept
{
    return std::min(2.0, 1.0 + frequencyHz / radiation.directivityHz);
}

double pressurePerAcceleration(const BodyMode& mode, const BodyRadiation& radiation) noexcept
{
    if (!(mode.radiationEfficiency > 0.0) || !(radiation.surfaceDensity > 0.0))
        return 0.0;
    const double D = directivity(radiation, mode.frequency);
    const double perVelocity = kAirDensity * kSpeedOfSound / radiation.listeningDistance *
                               std::sqrt(D * mode.radiationEfficiency * mode.effectiveMass /
                                         (4.0 * std::numbers::pi * radiation.surfaceDensity));
    const double compactness = std::hypot(1.0, mode.frequency / radiation.unityEfficiencyHz);
    return mode.radiationGain * mode.radiationSign * perVelocity * compactness / (kTwoPi * mode.frequency);
}

double radiatedShare(const BodyMode& mode, const BodyRadiation& radiation) noexcept
{
    const double etaRadiated = kAirDensity * kSpeedOfSound * mode.radiationEfficiency /
                               (radiation.surfaceDensity * kTwoPi * mode.frequency);
    return etaRadiated * mode.q;
}

std::complex<double> radiativity(const BodyParameters& body, double frequencyHz)
{
    const double w = kTwoPi * frequencyHz;
    const std::complex<double> iw(0.0, w);
    std::complex<double> p = 0.0;
    for (const auto& m : body.modes)
    {
        const double wk = kTwoPi * m.frequency;
        const std::complex<double> Yk =
            iw / (m.effectiveMass * std::complex<double>(wk * wk - w * w, w * wk / m.q));
        p += pressurePerAcceleration(m, body.radiation) * iw * Yk;
    }
    return p / std::complex<double>(1.0, frequencyHz / body.radiation.unityEfficiencyHz);
}

} // namespace rosin::physics
