#pragma once
// The instrument body at the bridge for the independent generator: the mode table Rosin's body uses (a
// handbook of the instrument, physics::BodyParameters), stepped here by impulse invariance. Each mode's
// velocity response to a force, h(t) = (1/m) e^{-s t} (cos wd t - (s/wd) sin wd t), is sampled (times the
// step) with the half-weight correction at t = 0, where h jumps: H(z) = T sum_n h(nT) z^-n - T h(0)/2. That
// keeps the bank's instantaneous answer y0 = sum T / (2 m_k) finite and its passband true to the continuous
// admittance ([Notes] eq. 5.2), and it is a different discretisation from Rosin's.
//
// Coupled to a waveguide end through [Notes] eq. (5.1a): the bridge velocity is history + y0 F.
#include <vector>

#include "core/physics/body/BodyParameters.h"

namespace rosin::discovery
{

class BodyResonators
{
  public:
    BodyResonators() = default;
    /// Modes above 0.45 sampleRate are left out (impulse invariance would alias them).
    BodyResonators(const physics::BodyParameters& body, double sampleRate);

    bool rigid() const noexcept { return modes_.empty(); }
    /// Bridge velocity without this step's force (m/s).
    double historyVelocity() const noexcept;
    /// Instantaneous admittance y0 (s/kg).
    double directAdmittance() const noexcept { return y0_; }
    /// Advances every mode with this step's force on the bridge (N).
    void advance(double force) noexcept;
    void reset() noexcept;

  private:
    struct Mode
    {
        double b0, b1, b2, a1, a2; ///< transposed direct form II
        double z1 = 0.0, z2 = 0.0;
    };
    std::vector<Mode> modes_;
    double y0_ = 0.0;
};

} // namespace rosin::discovery
