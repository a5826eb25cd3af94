#pragma once
// Friction "laws" used only by tests: they let a test drive the linear string with a known force.
#include <vector>

#include "core/physics/friction/FrictionLaw.h"

namespace rosin::test
{

/// Applies a prescribed force sequence at the bow point, whatever the string does (the bow is a force
/// source, not a friction contact): f[k] = forces[k], dv = dvHistory + f / 2Z.
class PrescribedForceLaw final : public physics::FrictionLaw
{
  public:
    explicit PrescribedForceLaw(std::vector<double> forces) : forces_(std::move(forces)) {}
    void prepare(double) override { reset(); }
    void reset() noexcept override { k_ = 0; }
    physics::JunctionSolution solve(const physics::JunctionInput& in) noexcept override
    {
        const double f = k_ < forces_.size() ? forces_[k_] : 0.0;
        ++k_;
        return {in.dvHistory + f / in.loadSlope, f, false};
    }
    double staticCoefficient(double) const noexcept override { return 0.0; }
    const char* name() const noexcept override { return "prescribed-force"; }

  private:
    std::vector<double> forces_;
    std::size_t k_ = 0;
};

} // namespace rosin::test
