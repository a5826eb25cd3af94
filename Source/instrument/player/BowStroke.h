#pragma once
// The bow on one string, sample by sample: at rest, starting (constant acceleration), sustaining, or being
// lifted. MidiGestureController owns one per string and decides when strokes start, change and end.
//
//  * Attack (Guettler's gesture): v_b[k] = v0 + d a k / fs, k counted from the event sample, computed from
//  the
//    index (no running sum, so no drift), until |v_b| reaches the target speed; v0 = 0 from rest, the current
//    velocity at a bow change (so the bow decelerates through zero and reverses at the same acceleration).
//    The velocity is NOT smoothed during the attack: the first slip depends on the exact velocity history.
//  * Sustain: speed, force, beta and finger follow their targets through one-pole smoothers (3 ms, snapping
//    to the first value): automation and controller steps become click-free moves that are still short
//    against the transients of interest. The attack's extra force relaxes to the nominal force (50 ms).
//  * Release: force and velocity fall linearly to exactly 0 over releaseSeconds (the bow leaves the string);
//    the string then rings on its own.
//  * Crossing (a slur onto another string): the bow arrives already moving, the force ramps in from 0 over
//    crossingSeconds while the string it leaves is lifted over the same time.
//  * Pluck (pizzicato): a finger, not the bow: it pulls the string at a constant speed with a firm grip for
//    the pull time and lets go (force and speed to 0 over pluckReleaseSeconds); the rosin law decides whether
//    the string slips out of the grip earlier, as a finger's does ([Notes §2], a pluck as a stick-slip
//    episode). Damp: a finger rests lightly on the string at rest (a stopped pizzicato note ending).
// Real-time: prepare() may compute exponentials; everything else is allocation-free and noexcept.
#include <cstdint>

#include "core/gesture/OnePoleSmoother.h"
#include "core/physics/voice/BowedStringVoice.h"

namespace rosin::player
{

struct StrokeSettings
{
    double smoothingSeconds = 0.003;       ///< force, speed, beta and finger smoothing
    double releaseSeconds = 0.02;          ///< bow lift: force and speed ramp to 0
    double attackForceRelaxSeconds = 0.05; ///< attack force multiplier back to 1 after the attack
    double crossingSeconds = 0.03;         ///< a string crossing's force ramp ([Notes]: LibreStrings' 30 ms)
    double pluckReleaseSeconds = 0.001;    ///< the plucking finger leaves the string
};

/// What the controller wants for this string now (before smoothing), SI units.
struct StrokeTargets
{
    double bowForce = 0.0; ///< nominal force, N
    double bowSpeed = 0.0; ///< |v_b| to sustain, m/s (> 0)
    double beta = 0.1;
    double finger = 1.0; ///< vibrating / open length
};

class BowStroke
{
  public:
    enum class Phase : std::uint8_t
    {
        Idle,
        Attack,
        Sustain,
        Release,
        Pluck,
        Damp
    };

    void prepare(double sampleRate, const StrokeSettings& settings = {});
    void reset() noexcept;

    /// Bow placed on the string at rest and accelerated at `acceleration` (m/s^2, > 0) in `direction` (+1
    /// down-bow, -1 up-bow). Force starts at forceMultiplier x the nominal force; finger snaps to `finger`.
    void startFromRest(double direction, double acceleration, double forceMultiplier, double finger) noexcept;
    /// Direction reversal: from the current velocity towards the opposite target at constant acceleration
    /// (also from a lift in progress: the bow had not left the string yet).
    void bowChange(double acceleration, double forceMultiplier) noexcept;
    /// Lift the bow: linear ramps of force and velocity to 0 (over releaseSeconds, or `seconds` if > 0).
    void lift(double seconds = 0.0) noexcept;
    /// A slur onto this string: the bow moving at `velocity` (signed, m/s) from the first sample, the force
    /// ramped in over crossingSeconds; the finger snaps to `finger` (placed before the bow arrives).
    void crossOnto(double velocity, double finger) noexcept;
    /// A pluck: pull at `velocity` (signed, m/s) with `force` (N) for `seconds`, then let go; the finger
    /// snaps to `finger`.
    void pluck(double velocity, double force, double seconds, double finger) noexcept;
    /// A finger rests on the string with `force` (N) and does not move, until the next stroke.
    void damp(double force) noexcept;

    /// The next sample's bow input.
    physics::BowInput next(const StrokeTargets& targets) noexcept;

    Phase phase() const noexcept { return phase_; }
    /// Strokes started from rest since reset (the controller alternates their direction, as players do).
    int strokesFromRest() const noexcept { return strokesFromRest_; }
    bool bowing() const noexcept { return phase_ == Phase::Attack || phase_ == Phase::Sustain; }
    double direction() const noexcept { return direction_; }
    double acceleration() const noexcept { return acceleration_; }
    /// The last sample's velocity and force (after smoothing), for inspection.
    double velocity() const noexcept { return velocity_; }
    double force() const noexcept { return force_; }

  private:
    double sampleRate_ = 48000.0;
    double releaseSamples_ = 960.0;
    double defaultReleaseSamples_ = 960.0;
    double crossingSamples_ = 1440.0;
    double pluckReleaseSeconds_ = 0.001;
    std::int64_t pluckSamples_ = 0;
    double pluckForce_ = 0.0;
    double crossingRamp_ = 1.0; // 0..1 while the force ramps in after a crossing
    double relaxCoefficient_ = 1.0;
    Phase phase_ = Phase::Idle;
    int strokesFromRest_ = 0;
    double direction_ = 1.0;
    double acceleration_ = 0.0;
    double startVelocity_ = 0.0;   // v0 of the attack or the release
    double startForce_ = 0.0;      // force at the start of the release
    std::int64_t phaseSample_ = 0; // k, samples since the phase began
    double attackForceMultiplier_ = 1.0;
    double velocity_ = 0.0;
    double force_ = 0.0;
    gesture::OnePoleSmoother forceSmoother_, speedSmoother_, betaSmoother_, fingerSmoother_;
};

} // namespace rosin::player
