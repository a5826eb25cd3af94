#pragma once
// Junction growth (contact ageing, [Notes §8.2]): the static friction of a polymer contact grows with the
// time it has been held, mu_s(t_h) = mu_s0 + beta_a ln(1 + t_h / tau_c), because the real contact area of
// the asperities creeps and grows while nothing slides. Any friction law of the source texts can age: this
// wrapper passes the wrapped law a normal force scaled by
//     g(t_h) = 1 + growth ln(1 + t_h / tau_c),    growth = beta_a / mu_s0,
// while the contact sticks (t_h = time since the last sliding sample), and the plain force while it slides
// (g(0) = 1: a slip breaks the junctions and the memory). Or, saturating (AgeingForm::Saturating),
//     g(t_h) = 1 + growth (1 - exp(-t_h / tau_c)),
// the form of an area that creeps towards a limit rather than on logarithmically: the data of a short hold
// cannot tell the two apart, a long one can. (HeldContactLaw: for the thermal laws the factor scales the
// contact area A(Fb), which is what ageing grows.)
#include <memory>

#include "core/physics/friction/HeldContactLaw.h"

namespace rosin::physics
{

enum class AgeingForm
{
    Logarithmic,
    Saturating
};

class JunctionGrowthLaw final : public HeldContactLaw
{
  public:
    /// growth: fractional increase of the static limit per e-fold of (1 + t_h / tau_c) (logarithmic) or at
    /// saturation, >= 0. tauSeconds: the hold time at which ageing sets in, > 0.
    JunctionGrowthLaw(std::unique_ptr<FrictionLaw> inner, double growth, double tauSeconds,
                      AgeingForm form = AgeingForm::Logarithmic);

    /// g(t_h) for the current hold time.
    double forceFactor() const noexcept override { return growthFactor(); }
    double growthFactor() const noexcept;
    double holdTime() const noexcept { return static_cast<double>(holdSamples_) * samplePeriod(); }

  private:
    void forget() noexcept override { holdSamples_ = 0; }
    /// The hold time counts samples stuck so far (creeping included); a sliding sample breaks the junctions.
    void observe(const JunctionSolution& s) noexcept override
    {
        holdSamples_ = s.sticking ? holdSamples_ + 1 : 0;
    }
    double growth_;
    double tau_;
    AgeingForm form_;
    long holdSamples_ = 0;
};

} // namespace rosin::physics
