#pragma once
// Creep during nominal sticking ([Galluzzo2017] section 5.3): a measured pre-slip force rises more slowly
// than rigid sticking predicts, as if the rosin layer yielded viscously before it lets go. This wrapper puts
// a dashpot of resistance eta (N s/m) in series with the wrapped law's sticking contact: whenever the wrapped
// law sticks, the string slides instead at
//     dv = 2Z dvh / (2Z + eta),    f = -eta dv,
// the intersection of the load line f = 2Z (dv - dvh) with the dashpot, so the force the contact carries
// while "stuck" is the rigid-sticking force times eta / (2Z + eta) and the string creeps behind the bow by
// f / eta. Sliding samples are the wrapped law's own. eta -> infinity recovers the wrapped law. The wrapped
// law advances its state with the creeping solution (FrictionLaw::solveCreeping): a thermal law's contact
// takes the creep's work, f^2 / eta, as heat. (It was once neglected as small; it is not: at eta = 60 N s/m
// and 1 N the contact creeps at 17 mm/s and takes 17 mW through every hold, two thirds of the mean power
// that Helmholtz motion's slips deposit at 0.05 m/s, 0.5 N, beta 0.09: 0.5 N x 0.55 m/s x beta = 25 mW.)
#include <memory>

#include "core/physics/friction/FrictionLaw.h"

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
