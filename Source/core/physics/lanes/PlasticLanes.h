#pragma once
// The plastic thermal law (PlasticThermalLaw.h) for all eight lanes at once: the same predictor, exact
// stick/slide solve, corrector and implicit heat-balance commit, with each lane's temperature,
// stationary-side history and previous power held side by side, each step computed in vectors across the
// lanes (one kernel per vector unit, KernelDispatch.h). The calibration table, the heat model's
// sum-of-exponentials and the contact geometry are shared (read from one prepared PlasticThermalLaw), so
// eight lanes keep one copy in cache instead of eight. A lane agrees with its own PlasticThermalLaw to
// rounding (the history sum is added in another order; tests/core/physics/VoiceLanesTest.cpp).
#include <memory>
#include <vector>

#include "core/physics/lanes/LaneFriction.h"
#include "core/physics/thermal/PlasticThermalLaw.h"

namespace rosin::physics
{

class PlasticLanes final : public LaneFriction
{
  public:
    /// `law` must be prepared (it holds the calibration and the heat model).
    explicit PlasticLanes(std::unique_ptr<PlasticThermalLaw> law);
    void reset() noexcept override;
    void resetLane(int lane) noexcept override;
    void solve(const LaneJunctionInput& in, LaneJunctionSolution& out) noexcept override;
    double contactTemperature(int lane) const noexcept override { return temperature_[lane]; }
    /// Sticking moves no heat (dv = 0): a stuck lane stays at ambient, where it holds yield stress x area.
    std::optional<double> restingLimit(double bowForce) const noexcept override;

  private:
    using Lanes = std::array<double, kLanes>;
    /// The force-dependent terms of each lane, recomputed when its bow force changes.
    void updateForces(const Lanes& bowForce) noexcept;
    /// One solid's SOE history for every lane (ConductingSide, lane by lane).
    struct SideLanes
    {
        std::vector<double> decay, weight; ///< r_m and w_m of the shared heat model
        std::vector<Lanes> history;        ///< u_m of every lane
        Lanes sum{};                       ///< H of every lane
        void prepare(const ConductingSide& side);
        void resetLane(int lane) noexcept;
        void advance(const Lanes& scaledFlux, const Lanes& washout) noexcept;
    };
    std::unique_ptr<PlasticThermalLaw> law_;
    SideLanes stationary_, moving_;
    Lanes temperature_{}, previousPower_{}, previousSpeed_{};
    Lanes force_{}, area_{};
    Lanes capacityRate_{}, advectionPerSpeed_{}, kernelScale_{}, invStationaryG0_{}, invMovingG0_{},
        washoutPerSpeed_{};
};

} // namespace rosin::physics
