#pragma once
// Junction growth (contact ageing, reference §8.2): the static friction of a polymer contact grows with the
// time it has been held, mu_s(t_h) = mu_s0 + beta_a ln(1 + t_h / tau_c), because the real contact area of
// the asperities creeps and grows while nothing slides. Any friction law of the seeds can age: this wrapper
// passes the wrapped law a normal force scaled by
//     g(t_h) = 1 + growth ln(1 + t_h / tau_c),    growth = beta_a / mu_s0,
// while the contact sticks (t_h = time since the last sliding sample), and the plain force while it slides
// (g(0) = 1: a slip breaks the junctions and the memory). Or, saturating (AgeingForm::Saturating),
//     g(t_h) = 1 + growth (1 - exp(-t_h / tau_c)),
// the form of an area that creeps towards a limit rather than on logarithmically: the data of a short hold
// cannot tell the two apart, a long one can. For the curve laws that scales the static limit
// mu_s N exactly; for the thermal laws it scales the contact area A(Fb), which is what ageing grows.
// Real-time safe; the wrapped law keeps its own state.
#include <memory>

#include "FrictionLaw.h"

namespace rosin::physics
{

enum class AgeingForm
{
    Logarithmic,
    Saturating
};

class JunctionGrowthLaw final : public FrictionLaw
{
  public:
    /// growth: fractional increase of the static limit per e-fold of (1 + t_h / tau_c) (logarithmic) or at
    /// saturation, >= 0. tauSeconds: the hold time at which ageing sets in, > 0.
    JunctionGrowthLaw(std::unique_ptr<FrictionLaw> inner, double growth, double tauSeconds,
                      AgeingForm form = AgeingForm::Logarithmic);

    void prepare(double sampleRate) override;
    void reset() noexcept override;
    JunctionSolution solve(const JunctionInput& in) noexcept override;
    /// The aged contact creeping (a creep wrapper outside this one): the inner law's solveCreeping.
    JunctionSolution solveCreeping(const JunctionInput& in, double eta) noexcept override;
    double contactTemperature() const noexcept override { return inner_->contactTemperature(); }
    /// The aged limit: the wrapped law's static coefficient at the force scaled by g(t_h) now, per N.
    double staticCoefficient(double bowForce) const noexcept override;
    const char* name() const noexcept override { return inner_->name(); }

    /// g(t_h) for the current hold time.
    double growthFactor() const noexcept;
    double holdTime() const noexcept { return holdSamples_ * T_; }

  private:
    JunctionInput aged(const JunctionInput& in) const noexcept;   ///< the bow force x growthFactor()
    JunctionSolution counted(const JunctionSolution& s) noexcept; ///< advances the hold time
    std::unique_ptr<FrictionLaw> inner_;
    double growth_;
    double tau_;
    AgeingForm form_;
    double T_ = 1.0 / 48000.0;
    long holdSamples_ = 0;
};

} // namespace rosin::physics
