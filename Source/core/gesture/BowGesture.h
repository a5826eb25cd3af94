#pragma once
// Turns a GestureScript into per-sample physics::BowInput.
//
//  * Segment i covers samples [round(S_i fs), round(S_{i+1} fs)), S_i the sum of the earlier durations.
//  * Ramps (force, speed, beta, finger) are linear in time: value = from + (to - from) t / seconds, with t
//  the
//    time since the segment start.
//  * Acceleration segments give v_b = v0 + a t exactly, t = k / fs at the segment's k-th sample, computed
//  from
//    the sample index (no running sum, so no drift), v0 the velocity the previous segment ended with.
//  * Force, beta, finger, and the bow velocity of speed segments, pass through a one-pole smoother
//    (OnePoleSmoother, default tau = 3 ms) that snaps to the first value. 3 ms (a -3 dB point near 53 Hz)
//    turns the step at a segment boundary into a click-free move, yet is short against the transients under
//    study (first slip and Helmholtz build-up take tens of ms). The bow velocity of acceleration segments is
//    NOT smoothed: the first slip of a constant-acceleration start depends on the exact velocity history.
//
// prepare() allocates; reset() and next() do not. After the last segment next() holds the final values.
#include <cstdint>
#include <vector>

#include "core/gesture/GestureScript.h"
#include "core/gesture/OnePoleSmoother.h"
#include "core/physics/voice/BowedStringVoice.h"

namespace rosin::gesture
{

class BowGesture
{
  public:
    static constexpr double kDefaultSmoothingSeconds = 0.003;

    BowGesture() = default;

    /// Off the audio thread. Validates the script (throws GestureError) and resolves every segment to sample
    /// boundaries and concrete start/end values. smoothingSeconds <= 0 disables the smoother.
    void prepare(const GestureScript& script, const GestureStart& start, double sampleRate,
                 double smoothingSeconds = kDefaultSmoothingSeconds);
    /// Back to the first sample; the smoothers will snap again. Real-time safe.
    void reset() noexcept;
    /// The bow input of the next sample. Real-time safe.
    physics::BowInput next() noexcept;

    std::int64_t totalSamples() const noexcept { return totalSamples_; }
    std::int64_t position() const noexcept { return position_; }
    bool finished() const noexcept { return position_ >= totalSamples_; }
    double sampleRate() const noexcept { return sampleRate_; }
    double smoothingSeconds() const noexcept { return smoothingSeconds_; }

  private:
    struct Linear
    {
        double from = 0.0;
        double to = 0.0;
        double at(double fraction) const noexcept { return from + (to - from) * fraction; }
    };
    struct Resolved
    {
        std::int64_t begin = 0, end = 0; // sample range [begin, end)
        double seconds = 1.0;            // nominal duration: the ramps reach `to` at t = seconds
        Linear force, beta, finger, speed;
        bool accelerating = false;
        double acceleration = 0.0; // m/s^2; velocity = speed.from + acceleration t
    };

    physics::BowInput evaluate(const Resolved& segment, std::int64_t sample) noexcept;

    std::vector<Resolved> segments_;
    std::size_t index_ = 0;
    std::int64_t position_ = 0;
    std::int64_t totalSamples_ = 0;
    double sampleRate_ = 48000.0;
    double smoothingSeconds_ = kDefaultSmoothingSeconds;
    OnePoleSmoother force_, beta_, finger_, velocity_;
};

} // namespace rosin::gesture
