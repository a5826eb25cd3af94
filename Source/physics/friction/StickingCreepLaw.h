#pragma once
// Creep during nominal sticking (seed 001 section 5.3): a measured pre-slip force rises more slowly than
// rigid sticking predicts, as if the rosin layer yielded viscously before it lets go. This wrapper puts a
// dashpot of resistance eta (N s/m) in series with the wrapped law's sticking contact: whenever the wrapped
// law sticks, the string slides instead at
//     dv = 2Z dvh / (2Z + eta),    f = -eta dv,
// the intersection of the load line f = 2Z (dv - dvh) with the dashpot, so the force the contact carries
// while "stuck" is the rigid-sticking force times eta / (2Z + eta) and the string creeps behind the bow by
// f / eta. Sliding samples are the wrapped law's own. eta -> infinity recovers the wrapped law. The wrapped
// law's state (temperature, hysteresis flag) advances with its own sticking solution: the heat of creep,
// f^2 / eta, is neglected (it is ~1e-3 of the sliding power at the creep speeds that matter).
#include <memory>

#include "FrictionLaw.h"

namespace rosin::physics
{

class StickingCreepLaw final : public FrictionLaw
{
  public:
    /// eta: creep resistance of the sticking contact, N s/m, > 0.
    StickingCreepLaw(std::unique_ptr<FrictionLaw> inner, double eta);

    void prepare(double sampleRate) override { inner_->prepare(sampleRate); }
    void reset() noexcept override { inner_->reset(); }
    JunctionSolution solve(const JunctionInput& in) noexcept override;
    double contactTemperature() const noexcept override { return inner_->contactTemperature(); }
    double staticCoefficient(double bowForce) const noexcept override
    {
        return inner_->staticCoefficient(bowForce);
    }
    const char* name() const noexcept override { return inner_->name(); }

    double resistance() const noexcept { return eta_; }

  private:
    std::unique_ptr<FrictionLaw> inner_;
    double eta_;
};

} // namespace rosin::physics
