#include "instrument/player/BowStroke.h"

#include <algorithm>
#include <cmath>

namespace rosin::player
{

void BowStroke::prepare(double sampleRate, const StrokeSettings& settings)
{
    sampleRate_ = sampleRate;
    releaseSamples_ = defaultReleaseSamples_ =
        std::max(1.0, std::round(settings.releaseSeconds * sampleRate));
    crossingSamples_ = std::max(1.0, std::round(settings.crossingSeconds * sampleRate));
    pluckReleaseSeconds_ = settings.pluckReleaseSeconds;
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
    crossingRamp_ = 1.0;
    pluckSamples_ = 0;
    pluckForce_ = 0.0;
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
    crossingRamp_ = 1.0;
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

void BowStroke::lift(double seconds) noexcept
{
    if (phase_ == Phase::Idle || phase_ == Phase::Release)
        return;
    if (phase_ == Phase::Damp)
    {
        phase_ = Phase::Idle;
        return;
    }
    releaseSamples_ =
        seconds > 0.0 ? std::max(1.0, std::round(seconds * sampleRate_)) : defaultReleaseSamples_;
    phase_ = Phase::Release;
    startVelocity_ = velocity_;
    startForce_ = force_;
    phaseSample_ = 0;
}

void BowStroke::crossOnto(double velocity, double finger) noexcept
{
    phase_ = Phase::Sustain;
    direction_ = velocity < 0.0 ? -1.0 : 1.0;
    velocity_ = velocity;
    speedSmoother_.snapTo(velocity);
    attackForceMultiplier_ = 1.0;
    crossingRamp_ = 0.0;
    forceSmoother_.snapTo(0.0);
    fingerSmoother_.snapTo(finger);
}

void BowStroke::pluck(double velocity, double force, double seconds, double finger) noexcept
{
    phase_ = Phase::Pluck;
    direction_ = velocity < 0.0 ? -1.0 : 1.0;
    startVelocity_ = velocity;
    pluckForce_ = force;
    pluckSamples_ = std::max<std::int64_t>(1, std::llround(seconds * sampleRate_));
    phaseSample_ = 0;
    fingerSmoother_.snapTo(finger);
}

void BowStroke::damp(double force) noexcept
{
    phase_ = Phase::Damp;
    pluckForce_ = force;
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
        crossingRamp_ = std::min(1.0, crossingRamp_ + 1.0 / crossingSamples_);
        velocity_ = speedSmoother_.process(direction_ * targets.bowSpeed);
        force_ = crossingRamp_ * forceSmoother_.process(targets.bowForce * attackForceMultiplier_);
        break;
    case Phase::Pluck:
        velocity_ = startVelocity_;
        force_ = pluckForce_;
        if (++phaseSample_ >= pluckSamples_)
            lift(pluckReleaseSeconds_);
        break;
    case Phase::Damp:
        velocity_ = 0.0;
        force_ = pluckForce_;
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
