#include "core/physics/lanes/RampStart.h"

#include <cmath>
#include <memory>

namespace rosin::physics
{

void RampStart::prepare(const BowedStringVoice& voice, double sampleRate)
{
    lanes_.prepare(voice, std::make_unique<StuckLanes>());
    sampleRate_ = sampleRate;
    unit_.clear();
    snapshots_.assign(1, LaneState{});
    lanes_.captureLane(0, snapshots_.front());
}

void RampStart::extend()
{
    LaneBowInput in; // lane 0 carries the unit start; the others stay at rest
    std::array<VoiceSample, kLanes> out;
    for (std::size_t i = 0; i < kStride; ++i)
    {
        in.bowForce[0] = 1.0; // unused: StuckLanes hold any force
        in.bowVelocity[0] = static_cast<double>(unit_.size()) / sampleRate_;
        lanes_.step(in, out);
        unit_.push_back(out[0]);
    }
    snapshots_.emplace_back();
    lanes_.captureLane(0, snapshots_.back());
}

std::size_t RampStart::skippable(double a, double limit, std::size_t maxSamples)
{
    if (!(a > 0.0) || !(limit > 0.0) || !std::isfinite(a * limit))
        return 0;
    const double reach = kMargin * limit / a; // unit friction force the trial's would reach at its margin
    std::size_t k = 0;
    for (;; ++k)
    {
        if (k + kStride > maxSamples)
            break;
        if (k == unit_.size())
            extend();
        if (std::abs(unit_[k].frictionForce) > reach || !unit_[k].sticking)
            break;
    }
    return k / kStride * kStride;
}

void RampStart::start(VoiceLanes& lanes, int lane, double a, std::size_t samples) const noexcept
{
    lanes.restoreLane(lane, snapshots_[samples / kStride], a);
}

} // namespace rosin::physics
