#include "instrument/player/BowStroke.h"

#include <algorithm>
#include <cmath>

namespace rosin::player
{

void BowStroke::prepare(double sampleRate, const StrokeSettings& settings)
{
    sampleRate_ = sampleRate;
    releaseSamples_ = std::max(1.0, std::round(settings.releaseSeconds * sampleRate));
    relaxCoefficient_ = settings.attackForceRelaxSeconds > 0.0
                            ? 1.0 - std::exp(-1.0 / (settings.attackForceRelaxSeconds * sampleRate))
                            : 1.0;
    for (gesture::OnePoleSmoother* s : {&forceSmoother_, &speedSmoother_, &betaSmoother_, &fingerSmoother_})
        s->prepare(settings.smoothingSeconds, sampleRate);
    reset();
}

void BowStroke::reset() noexcept
{
    phase_ = Phase::Idle;
    strokesFromRest_ = 0;
    direction_ = 1.0;
    acceleration_ = 0.0;
    startVelocity_ = startForce_ = 0.0;
    phaseSample_ = 0;
    attackForceMultiplier_ = 1.0;
    velocity_ = force_ = 0.0;
    for (gesture::OnePoleSmoother* s : {&forceSmoother_, &speedSmoother_, &betaSmoother_, &fingerSmoother_})
        s->reset();
}

void BowStroke::startFromRest(double direction, double acceleration, double forceMultiplier,
                              double finger) noexcept
{
    phase_ = Phase::Attack;
    ++strokesFromRest_;
    direction_ = direction < 0.0 ? -1.0 : 1.0;
    acceleration_ = acceleration;
    startVelocity_ = 0.0;
    phaseSample_ = 0;
    attackForceMultiplier_ = forceMultiplier;
    // The bow lands with its force at once (the smoother snaps), and the finger is down before the bow moves.
    forceSmoother_.reset();
    fingerSmoother_.snapTo(finger);
}

void BowStroke::bowChange(double acceleration, double forceMultiplier) noexcept
{
    phase_ = Phase::Attack;
    direction_ = -direction_;
    acceleration_ = acceleration;
    startVelocity_ = velocity_;
    phaseSample_ = 0;
    attackForceMultiplier_ = forceMultiplier;
}

void BowStroke::lift() noexcept
{
    if (phase_ == Phase::Idle || phase_ == Phase::Release)
        return;
    phase_ = Phase::Release;
    startVelocity_ = velocity_;
    startForce_ = force_;
    phaseSample_ = 0;
}

physics::BowInput BowStroke::next(const StrokeTargets& targets) noexcept
{
    physics::BowInput in;
    in.beta = betaSmoother_.process(targets.beta);
    in.fingerRatio = fingerSmoother_.process(targets.finger);

    switch (phase_)
    {
    case Phase::Idle:
        velocity_ = force_ = 0.0;
        break;
    case Phase::Attack:
    {
        // Division by the rate, as in BowGesture: v = v0 + d a (k / fs) exactly.
        const double t = static_cast<double>(phaseSample_++) / sampleRate_;
        double v = startVelocity_ + direction_ * acceleration_ * t;
        if (direction_ * v >= targets.bowSpeed)
        {
            v = direction_ * targets.bowSpeed;
            phase_ = Phase::Sustain;
            speedSmoother_.snapTo(v);
        }
        velocity_ = v;
        force_ = forceSmoother_.process(targets.bowForce * attackForceMultiplier_);
        break;
    }
    case Phase::Sustain:
        attackForceMultiplier_ += relaxCoefficient_ * (1.0 - attackForceMultiplier_);
        velocity_ = speedSmoother_.process(direction_ * targets.bowSpeed);
        force_ = forceSmoother_.process(targets.bowForce * attackForceMultiplier_);
        break;
    case Phase::Release:
    {
        const double fraction = static_cast<double>(phaseSample_++) / releaseSamples_;
        if (fraction >= 1.0)
        {
            phase_ = Phase::Idle;
            velocity_ = force_ = 0.0;
        }
        else
        {
            velocity_ = startVelocity_ * (1.0 - fraction);
            force_ = startForce_ * (1.0 - fraction);
        }
        forceSmoother_.snapTo(force_);
        speedSmoother_.snapTo(velocity_);
        break;
    }
    }
    in.bowForce = force_;
    in.bowVelocity = velocity_;
    return in;
}

} // namespace rosin::player
