#include "instrument/player/Vibrato.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rosin::player
{

void Vibrato::prepare(double sampleRate, std::uint32_t seed) noexcept
{
    sampleRate_ = sampleRate;
    seed_ = seed;
    driftCoefficient_ = 1.0 - std::exp(-1.0 / (kDriftSeconds * sampleRate));
    depth_.prepare(kDepthSmoothingSeconds, sampleRate);
    reset();
}

void Vibrato::reset() noexcept
{
    active_ = false;
    samplesSinceStart_ = 0;
    phase_ = 0.0;
    depthDrift_ = rateDrift_ = depthTarget_ = rateTarget_ = 0.0;
    depth_.reset();
    cents_ = 0.0;
    state_ = seed_ % 2147483647u == 0 ? 1u : seed_ % 2147483647u;
}

double Vibrato::uniform() noexcept
{
    state_ = static_cast<std::uint32_t>((static_cast<std::uint64_t>(state_) * 48271u) % 2147483647u);
    return 2.0 * (static_cast<double>(state_) - 1.0) / 2147483645.0 - 1.0;
}

void Vibrato::newDriftTargets() noexcept
{
    depthTarget_ = kDepthDrift * uniform();
    rateTarget_ = kRateDrift * uniform();
}

void Vibrato::startNote(std::uint32_t noteSerial) noexcept
{
    active_ = true;
    samplesSinceStart_ = 0;
    phase_ = 0.0;
    const std::uint32_t mixed = (seed_ ^ (noteSerial * 2654435761u)) % 2147483647u;
    state_ = mixed == 0 ? 1u : mixed;
    newDriftTargets();
    depthDrift_ = depthTarget_;
    rateDrift_ = rateTarget_;
    newDriftTargets();
}

double Vibrato::next(double depthCents, double rateHz, double delaySeconds) noexcept
{
    const double depth = depth_.process(std::max(0.0, depthCents));
    if (!active_)
    {
        cents_ = 0.0;
        return 1.0;
    }
    const double t = static_cast<double>(samplesSinceStart_++) / sampleRate_ - std::max(0.0, delaySeconds);
    double envelope = 0.0;
    if (t > 0.0)
    {
        const double x = std::min(1.0, t / kFadeInSeconds);
        envelope = x * x * (3.0 - 2.0 * x);
    }
    depthDrift_ += driftCoefficient_ * (depthTarget_ - depthDrift_);
    rateDrift_ += driftCoefficient_ * (rateTarget_ - rateDrift_);
    cents_ = depth * envelope * (1.0 + depthDrift_) * std::sin(2.0 * std::numbers::pi * phase_);
    // The phase runs from the note's start, so the first swing after the delay starts from the centre.
    phase_ += std::max(0.0, rateHz) * (1.0 + rateDrift_) / sampleRate_;
    if (phase_ >= 1.0)
    {
        phase_ -= 1.0;
        newDriftTargets();
    }
    return std::exp2(-cents_ / 1200.0);
}

} // namespace rosin::player
