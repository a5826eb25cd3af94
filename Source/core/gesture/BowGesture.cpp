#include "core/gesture/BowGesture.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/gesture/GestureLimits.h"

namespace rosin::gesture
{

namespace
{
double resolveFrom(const std::optional<Ramp>& ramp, double previous)
{
    return ramp && ramp->from ? *ramp->from : previous;
}
double resolveTo(const std::optional<Ramp>& ramp, double previous)
{
    return ramp ? ramp->to : previous;
}
} // namespace

void BowGesture::prepare(const GestureScript& script, const GestureStart& start, double sampleRate,
                         double smoothingSeconds)
{
    if (!(sampleRate > 0.0) || !std::isfinite(sampleRate))
        throw std::invalid_argument("BowGesture: sample rate must be positive");
    validateScript(script, start);

    sampleRate_ = sampleRate;
    smoothingSeconds_ = smoothingSeconds;
    segments_.clear();
    segments_.reserve(script.segments.size());

    double force = start.force, beta = start.beta, finger = start.finger, speed = start.speed;
    double elapsed = 0.0;
    std::int64_t begin = 0;
    for (const Segment& s : script.segments)
    {
        elapsed += s.seconds;
        Resolved r;
        r.begin = begin;
        r.end = static_cast<std::int64_t>(std::llround(elapsed * sampleRate));
        r.seconds = s.seconds;
        r.force = {resolveFrom(s.force, force), resolveTo(s.force, force)};
        r.beta = {resolveFrom(s.beta, beta), resolveTo(s.beta, beta)};
        r.finger = {resolveFrom(s.finger, finger), resolveTo(s.finger, finger)};
        if (s.acceleration)
        {
            r.accelerating = true;
            r.acceleration = *s.acceleration;
            // The end velocity is the one the next sample would have, so a following segment continues
            // the same straight line.
            const double duration = static_cast<double>(r.end - r.begin) / sampleRate;
            r.speed = {speed, speed + r.acceleration * duration};
        }
        else
        {
            r.speed = {resolveFrom(s.speed, speed), resolveTo(s.speed, speed)};
        }
        force = r.force.to;
        beta = r.beta.to;
        finger = r.finger.to;
        speed = r.speed.to;
        begin = r.end;
        segments_.push_back(r);
    }
    totalSamples_ = begin;

    for (OnePoleSmoother* smoother : {&force_, &beta_, &finger_, &velocity_})
        smoother->prepare(smoothingSeconds, sampleRate);
    reset();
}

void BowGesture::reset() noexcept
{
    index_ = 0;
    position_ = 0;
    for (OnePoleSmoother* smoother : {&force_, &beta_, &finger_, &velocity_})
        smoother->reset();
}

physics::BowInput BowGesture::next() noexcept
{
    if (segments_.empty())
        return {};
    // Segments shorter than one sample (after rounding) are skipped; their end values still carry over.
    while (index_ + 1 < segments_.size() && position_ >= segments_[index_].end)
        ++index_;
    // Past the end: hold the last segment's end values.
    const std::int64_t sample = std::min(position_, segments_[index_].end);
    const physics::BowInput in = evaluate(segments_[index_], sample);
    if (position_ < totalSamples_)
        ++position_;
    else
        position_ = totalSamples_;
    return in;
}

physics::BowInput BowGesture::evaluate(const Resolved& segment, std::int64_t sample) noexcept
{
    // Division by the rate, not multiplication by its inverse: v = a * (k / fs) exactly as documented.
    const double t = static_cast<double>(sample - segment.begin) / sampleRate_;
    const double fraction = t / segment.seconds;

    physics::BowInput in;
    in.bowForce = force_.process(segment.force.at(fraction));
    in.beta = beta_.process(segment.beta.at(fraction));
    in.fingerRatio = finger_.process(segment.finger.at(fraction));
    if (segment.accelerating)
    {
        in.bowVelocity = segment.speed.from + segment.acceleration * t;
        velocity_.snapTo(in.bowVelocity); // a later speed segment smooths on from here
    }
    else
    {
        in.bowVelocity = velocity_.process(segment.speed.at(fraction));
    }
    return in;
}

} // namespace rosin::gesture
