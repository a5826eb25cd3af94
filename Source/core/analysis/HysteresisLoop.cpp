#include "core/analysis/HysteresisLoop.h"

#include <cstdio>

namespace rosin::analysis
{

HysteresisLoop::HysteresisLoop(double fromSeconds, double toSeconds, double sampleRate)
    : from_(fromSeconds), to_(toSeconds), sampleRate_(sampleRate)
{
    if (!(fromSeconds >= 0.0) || !(toSeconds > fromSeconds) || !(sampleRate > 0.0))
        throw std::invalid_argument("HysteresisLoop: need 0 <= from < to and a positive sample rate");
}

void HysteresisLoop::add(const physics::VoiceSample& s)
{
    const double t = static_cast<double>(index_++) / sampleRate_;
    if (t < from_ || t >= to_)
        return;
    points_.push_back({t, s.bowPointVelocity - s.bowVelocity, s.frictionForce, s.contactTemperature});
    if (s.sticking)
        ++sticking_;
}

double HysteresisLoop::stickingFraction() const noexcept
{
    return points_.empty() ? 0.0 : static_cast<double>(sticking_) / static_cast<double>(points_.size());
}

double HysteresisLoop::signedArea() const noexcept
{
    double twice = 0.0;
    for (std::size_t i = 0; i + 1 < points_.size(); ++i)
        twice += points_[i].slidingSpeed * points_[i + 1].frictionForce -
                 points_[i + 1].slidingSpeed * points_[i].frictionForce;
    return 0.5 * twice;
}

std::string HysteresisLoop::csv() const
{
    std::string text = "time,slidingSpeed,frictionForce,contactTemperature\n";
    char line[160];
    for (const auto& p : points_)
    {
        std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g\n", p.time, p.slidingSpeed, p.frictionForce,
                      p.contactTemperature);
        text += line;
    }
    return text;
}

} // namespace rosin::analysis
