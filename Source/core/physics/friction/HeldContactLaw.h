#pragma once
// The base of the friction effects that change how much a held contact can carry (JunctionGrowthLaw:
// ageing with hold time; BreakawayMarginLaw: a margin until the first slip). Each passes the wrapped law
// the bow force times its own factor, watches each sample's solution to advance its memory, and reports
// the wrapped law's static coefficient at the scaled force, times the factor. For the curve laws that
// scales the static limit exactly; for the thermal laws it scales the contact area A(Fb). Real-time safe;
// the wrapped law keeps its own state.
#include <memory>

#include "core/physics/friction/FrictionLaw.h"

namespace rosin::physics
{

class HeldContactLaw : public FrictionLaw
{
  public:
    void prepare(double sampleRate) override;
    void reset() noexcept override;
    JunctionSolution solve(const JunctionInput& in) noexcept override;
    /// The held contact creeping (a creep wrapper outside this one): the wrapped law's solveCreeping.
    JunctionSolution solveCreeping(const JunctionInput& in, double eta) noexcept override;
    double contactTemperature() const noexcept override { return inner_->contactTemperature(); }
    /// The wrapped law's static coefficient at the force scaled by forceFactor() now, per N.
    double staticCoefficient(double bowForce) const noexcept override;
    const char* name() const noexcept override { return inner_->name(); }

    /// What the bow force is multiplied by this sample.
    virtual double forceFactor() const noexcept = 0;

  protected:
    /// Throws std::invalid_argument (naming `who`) when there is no law to wrap.
    HeldContactLaw(std::unique_ptr<FrictionLaw> inner, const char* who);
    /// Clear the memory (prepare and reset).
    virtual void forget() noexcept = 0;
    /// Advance the memory by one sample that ended in `solution`.
    virtual void observe(const JunctionSolution& solution) noexcept = 0;
    const FrictionLaw& inner() const noexcept { return *inner_; }
    double samplePeriod() const noexcept { return T_; }

  private:
    JunctionInput scaled(const JunctionInput& in) const noexcept;
    JunctionSolution observed(const JunctionSolution& s) noexcept;
    std::unique_ptr<FrictionLaw> inner_;
    double T_ = 1.0 / 48000.0;
};

} // namespace rosin::physics
