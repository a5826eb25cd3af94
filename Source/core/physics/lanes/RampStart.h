#pragma once
// The sticking start of a trial whose bow accelerates uniformly from rest (a Guettler attack, v_b = a t).
// Until its first slip the string sticks to the bow: the junction holds dv = 0 with whatever force that
// takes, the string, torsion and body are linear, and an exact law's state stays at rest
// (LaneFriction::restingLimit). The whole state is then a times that of a unit-acceleration start, and so
// is the friction force. One unit start per bow position, run with lanes that cannot slip (StuckLanes) and
// kept as snapshots every kStride samples, lets a trial begin at the last snapshot before its friction force
// could reach its sticking limit (with a 5 % margin for rounding), instead of computing the stuck samples:
// about a fifth of a Guettler scan's samples. The snapshots are scaled in double and rounded to the modes'
// float, so a trial started this way agrees with one computed from rest to rounding.
#include <cstddef>
#include <vector>

#include "core/physics/lanes/VoiceLanes.h"

namespace rosin::physics
{

class RampStart
{
  public:
    static constexpr std::size_t kStride = 64;
    /// Share of the sticking limit a skipped sample's friction force may reach.
    static constexpr double kMargin = 0.95;

    /// Off the audio thread: the unit start for the voice's current bow position (the snapshots are
    /// computed as trials need them).
    void prepare(const BowedStringVoice& voice, double sampleRate);

    /// Samples a trial at acceleration a (m/s^2) whose lanes hold `limit` (N) at rest can skip: a multiple of
    /// kStride, at most maxSamples, 0 if none.
    std::size_t skippable(double a, double limit, std::size_t maxSamples);

    /// Puts a lane of `lanes` in the state of the skipped start: a times the unit state after `samples`
    /// (a value skippable() returned).
    void start(VoiceLanes& lanes, int lane, double a, std::size_t samples) const noexcept;

    /// The unit start's output at sample k < samples computed (bridge and friction force for a = 1 m/s^2).
    const VoiceSample& unitSample(std::size_t k) const noexcept { return unit_[k]; }

  private:
    void extend(); ///< kStride more samples and a snapshot

    VoiceLanes lanes_;
    double sampleRate_ = 48000.0;
    std::vector<VoiceSample> unit_;
    std::vector<LaneState> snapshots_; ///< [j]: the state after j x kStride samples
};

} // namespace rosin::physics
