#pragma once
// The output stage's last guard: identity up to the knee, then a tanh shoulder that approaches the ceiling. A
// hard clamp at full scale turned the bursts some friction laws produce at a bow start (the viscous law's
// forward slips reach 20 N of bridge force against ~1 N in Helmholtz motion) into square-topped clicks; the
// shoulder rounds them, keeps the slope continuous and the output bounded.
#include <cmath>

namespace rosin::engine
{

inline constexpr double kSoftClipKnee = 0.8;
inline constexpr double kSoftClipCeiling = 1.0;

/// |result| <= kSoftClipCeiling for every x (equal only where tanh rounds to 1); x itself for |x| <=
/// kSoftClipKnee; odd, increasing.
inline double softClip(double x) noexcept
{
    const double magnitude = std::abs(x);
    if (magnitude <= kSoftClipKnee)
        return x;
    constexpr double room = kSoftClipCeiling - kSoftClipKnee;
    const double shoulder = kSoftClipKnee + room * std::tanh((magnitude - kSoftClipKnee) / room);
    return std::copysign(shoulder, x);
}

} // namespace rosin::engine
