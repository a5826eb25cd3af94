#pragma once
// Vibrato as the stopping finger rocks: a multiplier of the finger ratio, so the stopped length moves and the
// pitch, the partials and the string's physics follow (the body turns that into the amplitude and timbre
// modulation listeners hear). Per string, sample by sample (allocation-free, noexcept after prepare()):
//   cents(t) = depth x e(t) x (1 + dd(t)) x sin(2 pi phase(t)),   phase' = rate (1 + dr(t))
//   e(t): 0 until the delay after the note's start, then a smoothstep to 1 over kFadeInSeconds;
//   dd, dr: slow random drifts (a new target each cycle, approached over kDriftSeconds), at most
//   kDepthDrift and kRateDrift, seeded per note from the seed and the note's serial, so a render is the
//   same every time and two notes do not vibrate alike.
// Figures (Resources/docs/playing.md, "Vibrato"): cellists 5-6 Hz, +-10-40 cents, starting 0.1-0.5 s
// into a note and growing over a fraction of a second, rate and extent drifting from cycle to cycle.
// The depth follows its control through a 20 ms smoother, so a CC1 move never steps the pitch.
#include <cstdint>

#include "core/gesture/OnePoleSmoother.h"

namespace rosin::player
{

class Vibrato
{
  public:
    static constexpr double kFadeInSeconds = 0.3;
    static constexpr double kDepthDrift = 0.08; ///< relative, peak
    static constexpr double kRateDrift = 0.04;  ///< relative, peak
    static constexpr double kDriftSeconds = 0.25;
    static constexpr double kDepthSmoothingSeconds = 0.02;

    void prepare(double sampleRate, std::uint32_t seed) noexcept;
    /// No vibrato, phase and drifts at rest.
    void reset() noexcept;
    /// A new note (not a legato continuation): the delay starts again and the drifts take the note's own
    /// random sequence.
    void startNote(std::uint32_t noteSerial) noexcept;
    /// The vibrato stops at once (an open string: no finger to rock).
    void stop() noexcept { active_ = false; }
    bool active() const noexcept { return active_; }

    /// This sample's finger multiplier 2^(-cents / 1200) for the given depth (cents), rate (Hz) and delay
    /// (s).
    double next(double depthCents, double rateHz, double delaySeconds) noexcept;
    /// The last sample's pitch offset, cents.
    double cents() const noexcept { return cents_; }

  private:
    double uniform() noexcept; // -1..1, from the note's own sequence
    void newDriftTargets() noexcept;

    double sampleRate_ = 48000.0;
    std::uint32_t seed_ = 1;
    std::uint32_t state_ = 1; // minstd (a = 48271, m = 2^31 - 1), computed here so every platform agrees
    bool active_ = false;
    std::int64_t samplesSinceStart_ = 0;
    double phase_ = 0.0; // cycles, 0..1
    double depthDrift_ = 0.0, rateDrift_ = 0.0;
    double depthTarget_ = 0.0, rateTarget_ = 0.0;
    double driftCoefficient_ = 0.0;
    gesture::OnePoleSmoother depth_;
    double cents_ = 0.0;
};

} // namespace rosin::player
