#pragma once
// The friction junctions of VoiceLanes' eight trials, one sample at a time (FrictionLaw.h for one trial).
// Two kinds: ScalarLaneFriction runs one FrictionLaw object per lane (every law and effect), PlasticLanes
// runs the plastic thermal law for all lanes at once (the scans' default law, and their largest cost).
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/lanes/LaneModes.h"

namespace rosin::physics
{

/// What every lane's junction knows before its friction force is chosen (JunctionInput per lane).
struct LaneJunctionInput
{
    std::array<double, kLanes> dvHistory{}; ///< m/s
    double loadSlope = 1.0;                 ///< kg/s, 2Z = 1/y0, the same for every lane
    std::array<double, kLanes> bowForce{};  ///< N
};

using LaneJunctionSolution = std::array<JunctionSolution, kLanes>;

class LaneFriction
{
  public:
    virtual ~LaneFriction() = default;
    virtual void reset() noexcept = 0;
    virtual void resetLane(int lane) noexcept = 0;
    /// One sample of every lane; advances each lane's state.
    virtual void solve(const LaneJunctionInput& in, LaneJunctionSolution& out) noexcept = 0;
    /// K above ambient (0 for laws without a temperature).
    virtual double contactTemperature(int lane) const noexcept = 0;
    /// FrictionLaw::restingLimit of the lanes' law: empty when a trial's sticking start cannot be scaled
    /// from another's (RampStart.h).
    virtual std::optional<double> restingLimit(double /*bowForce*/) const noexcept { return std::nullopt; }
};

/// Every lane sticks, whatever the force: the sticking branch of the exact laws (plastic, friction curves),
/// for a start that must not slip (RampStart.h).
class StuckLanes final : public LaneFriction
{
  public:
    void reset() noexcept override {}
    void resetLane(int) noexcept override {}
    void solve(const LaneJunctionInput& in, LaneJunctionSolution& out) noexcept override;
    double contactTemperature(int) const noexcept override { return 0.0; }
};

/// One prepared FrictionLaw per lane.
class ScalarLaneFriction final : public LaneFriction
{
  public:
    explicit ScalarLaneFriction(std::vector<std::unique_ptr<FrictionLaw>> laws);
    void reset() noexcept override;
    void resetLane(int lane) noexcept override { laws_[lane]->reset(); }
    void solve(const LaneJunctionInput& in, LaneJunctionSolution& out) noexcept override;
    double contactTemperature(int lane) const noexcept override { return laws_[lane]->contactTemperature(); }
    /// The lanes' law's (FrictionLaw::restingLimit).
    std::optional<double> restingLimit(double bowForce) const noexcept override
    {
        return laws_.front()->restingLimit(bowForce);
    }

  private:
    std::vector<std::unique_ptr<FrictionLaw>> laws_;
};

/// The lanes' friction for a law made by `makeLaw` (a fresh, unprepared law per call): the plastic law
/// lane-wise (PlasticLanes), any other law (or a law with effects) as one prepared object per lane.
std::unique_ptr<LaneFriction> makeLaneFriction(const std::function<std::unique_ptr<FrictionLaw>()>& makeLaw,
                                               double sampleRate);

} // namespace rosin::physics
