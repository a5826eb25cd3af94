#include "instrument/player/FingerGlide.h"

#include <algorithm>
#include <cmath>

namespace rosin::player
{

double slurSeconds(int velocity, double longestSeconds) noexcept
{
    const double x =
        std::clamp((kFastVelocity - velocity) / static_cast<double>(kFastVelocity - kSlowVelocity), 0.0, 1.0);
    return kFastPlacementSeconds + x * std::max(0.0, longestSeconds - kFastPlacementSeconds);
}

void FingerGlide::prepare(double sampleRate) noexcept
{
    sampleRate_ = sampleRate;
    reset();
}

void FingerGlide::start(double from, double to, double seconds) noexcept
{
    logFrom_ = std::log(from);
    logTo_ = std::log(to);
    to_ = to;
    total_ = std::max(1L, std::lround(seconds * sampleRate_));
    remaining_ = total_;
}

double FingerGlide::next() noexcept
{
    if (remaining_ <= 0)
        return to_;
    --remaining_;
    const double x = 1.0 - static_cast<double>(remaining_) / static_cast<double>(total_);
    const double s = x * x * (3.0 - 2.0 * x);
    return std::exp(logFrom_ + s * (logTo_ - logFrom_));
}

} // namespace rosin::player
