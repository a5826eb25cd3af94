#pragma once
// A friction-curve law: the classical ([Galluzzo2017] eq. 1) or reconstructed ([Galluzzo2017] eq. 2) curve,
// solved exactly with the hysteresis rule.
#include <algorithm>
#include <optional>

#include "core/physics/friction/CurveJunctionSolver.h"
#include "core/physics/friction/FrictionCurves.h"

namespace rosin::physics
{

template <typename Curve> class CurveFrictionLaw final : public FrictionLaw
{
  public:
    CurveFrictionLaw(Curve curve, const char* lawName) : curve_(curve), name_(lawName) {}
    void prepare(double) override { reset(); }
    void reset() noexcept override { memory_ = {}; }
    JunctionSolution solve(const JunctionInput& in) noexcept override
    {
        return solveCurveJunction(curve_, in, memory_);
    }
    double staticCoefficient(double) const noexcept override { return curve_.mu(0.0); }
    /// The hysteresis rule's sticking (solveCurveJunction) leaves the memory as reset() does.
    std::optional<double> restingLimit(double bowForce) const noexcept override
    {
        return std::max(bowForce, 0.0) * curve_.staticMu();
    }
    const char* name() const noexcept override { return name_; }

  private:
    Curve curve_;
    const char* name_;
    CurveJunctionMemory memory_;
};

using ClassicalFrictionLaw = CurveFrictionLaw<ClassicalCurve>;
using ReconstructedFrictionLaw = CurveFrictionLaw<ReconstructedCurve>;

} // namespace rosin::physics
