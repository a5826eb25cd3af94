#include "core/gesture/GestureLimits.h"

#include <charconv>
#include <cmath>

namespace rosin::gesture
{

namespace
{
std::string describeError(const std::string& field, const std::string& expected, const std::string& got)
{
    std::string text = "field \"" + field + "\": expected " + expected;
    if (!got.empty())
        text += " but got " + got;
    return text;
}
} // namespace

GestureError::GestureError(std::string field, std::string expected, std::string got)
    : std::invalid_argument(describeError(field, expected, got)), field_(std::move(field)),
      expected_(std::move(expected)), got_(std::move(got))
{
}

void requireInRange(const std::string& field, double value, const Range& range)
{
    if (!range.contains(value))
        throw GestureError(field, range.describe(), formatNumber(value));
}

namespace
{
// Checks a ramp and returns the value it leaves the quantity at.
double checkRamp(const std::string& field, const std::optional<Ramp>& ramp, double previous,
                 const Range& range)
{
    if (!ramp)
        return previous;
    if (ramp->from)
        requireInRange(field + ".from", *ramp->from, range);
    requireInRange(ramp->from ? field + ".to" : field, ramp->to, range);
    return ramp->to;
}
} // namespace

void validateScript(const GestureScript& script, const GestureStart& start)
{
    if (script.segments.empty())
        throw GestureError("segments", "at least one segment", "none");
    double speed = start.speed;
    for (std::size_t i = 0; i < script.segments.size(); ++i)
    {
        const Segment& s = script.segments[i];
        const std::string at = "segments[" + std::to_string(i) + "]";
        requireInRange(at + ".seconds", s.seconds, limits::seconds);
        if (s.speed && s.acceleration)
            throw GestureError(at, "either \"speed\" or \"acceleration\", not both", "both");
        checkRamp(at + ".force", s.force, start.force, limits::force);
        checkRamp(at + ".beta", s.beta, start.beta, limits::beta);
        checkRamp(at + ".finger", s.finger, start.finger, limits::finger);
        speed = checkRamp(at + ".speed", s.speed, speed, limits::speed);
        if (s.acceleration)
        {
            requireInRange(at + ".acceleration", *s.acceleration, limits::acceleration);
            // The bow may not be driven past the speed limit by integrating the acceleration.
            const double end = speed + *s.acceleration * s.seconds;
            if (!limits::speed.contains(end))
                throw GestureError(
                    at + ".acceleration",
                    "an acceleration that keeps the bow speed within -5..5 m/s over the segment",
                    formatNumber(*s.acceleration) + " (reaching " + formatNumber(end) + " m/s)");
            speed = end;
        }
    }
    const double total = script.totalSeconds();
    if (!limits::totalSeconds.contains(total))
        throw GestureError("segments",
                           "a total duration of at most " + formatNumber(limits::totalSeconds.max) + " s",
                           formatNumber(total) + " s");
}

} // namespace rosin::gesture
