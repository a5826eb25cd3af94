#pragma once
// One of the two solids that touch the contact disc ([Notes §2.3a]): its conduction memory as the
// sum-of-exponentials history of eq. 2.9, u_m[n+1] = s r_m (u_m[n] + w_m Q[n]), with r_m = exp(-dt/tau_m),
// w_m = c_m tau_m (1 - r_m) and s the washout of this step (1 for the stationary side and for a stuck
// moving side; washout::decay for a sliding one). The surface temperature of the solid under the contact
// is then g0 Q[n] + H[n], H = sum u_m.
#include <vector>

#include "core/physics/thermal/ConductionKernel.h"
#include "core/physics/thermal/ThermalMaterial.h"

namespace rosin::physics
{

class ConductingSide
{
  public:
    /// Off the audio thread (allocates): fits the SOE of a disc of `radius` on `material` at step dt.
    void prepare(double radius, const ThermalMaterial& material, double dt);
    void reset() noexcept;

    /// H for the next step, K (at the area the fluxes were scaled to).
    double historySum() const noexcept { return historySum_; }
    /// First-step weight g0 = int_0^dt G_avg dt at the fitted radius, K/W.
    double firstStepWeight() const noexcept { return kernel_.firstStepWeight(); }
    /// Deposits this step's flux (W, already scaled to the fitted area) and decays the history by
    /// washout * r_m. O(M), allocation-free.
    void advance(double scaledFlux, double washout) noexcept;
    /// Steady resistance of the scheme at a constant washout per step (K/W at the fitted area):
    /// g0 f + sum_m s r_m w_m d / (1 - s r_m), with s its decay, d its deposit factor and f its first-step
    /// factor (Washout.h); s = d = f = 1 without washout.
    double discreteSteadyResistance(double washoutDecay, double depositFactor,
                                    double firstStepFactor) const noexcept;

    const ConductionKernel& kernel() const noexcept { return kernel_; }
    /// r_m and w_m, padded with silent terms (0, 0) to whole kernel blocks: longer than
    /// kernel().coefficients().
    const std::vector<double>& decays() const noexcept { return decay_; }
    const std::vector<double>& weights() const noexcept { return weight_; } ///< w_m, K/W (padded likewise)

  private:
    ConductionKernel kernel_;
    std::vector<double> decay_, weight_, history_;
    double historySum_ = 0.0;
};

} // namespace rosin::physics
