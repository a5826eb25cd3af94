#pragma once
// The left hand between two notes of a slur: a finger placed quickly or a slide along the string, as the
// finger ratio moves from one note's to the next along a smoothstep in log frequency (so the pitch moves
// monotonically, slowest at both ends, as a hand accelerates and brakes). Allocation-free, noexcept.
// How long it takes is the landing note's velocity (slurSeconds): SWAM and LibreStrings split legato from
// portamento the same way, a hard landing being a fast finger and a soft one a slide.

namespace rosin::player
{

/// Time for a slur landing at `velocity` (1..127): kFastPlacementSeconds at kFastVelocity and above (a
/// finger falls in a few ms), `longestSeconds` at kSlowVelocity and below, linear in between.
double slurSeconds(int velocity, double longestSeconds) noexcept;
inline constexpr double kFastPlacementSeconds = 0.015;
inline constexpr int kFastVelocity = 100;
inline constexpr int kSlowVelocity = 30;

class FingerGlide
{
  public:
    void prepare(double sampleRate) noexcept;
    void reset() noexcept { remaining_ = 0; }
    /// From finger ratio `from` to `to` over `seconds`.
    void start(double from, double to, double seconds) noexcept;
    bool gliding() const noexcept { return remaining_ > 0; }
    /// This sample's finger ratio; once the glide is over, `to`.
    double next() noexcept;

  private:
    double sampleRate_ = 48000.0;
    double logFrom_ = 0.0, logTo_ = 0.0, to_ = 1.0;
    long total_ = 1, remaining_ = 0;
};

} // namespace rosin::player
