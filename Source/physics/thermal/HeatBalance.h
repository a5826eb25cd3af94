#pragma once
// Single contact temperature of the rosin layer (Smith & Woodhouse 2000, as reconstructed in reference
// §2.3-2.5): heat balance
//     C dT/dt = P - Q_adv - Q_mov - Q_stat                                   (reference eq. 2.4)
// with layer capacity C = rho c pi a^2 delta, advection Q_adv = rho c w delta |dv| T (w = ratio * a),
// moving-surface conduction Q_mov = pi a^2 e sqrt(3 |dv| / (8 a)) T (e = sqrt(K rho c)), and conduction
// into the stationary side (string) by convolution with the disc Green's function, approximated by a sum
// of exponentials. Time marching: implicit (backward Euler) layer + exact-in-time SOE history (eq. 2.9),
// stable for any time step.
#include <vector>

#include "ContactParameters.h"
#include "StationaryKernel.h"

namespace rosin::physics
{

class HeatBalance
{
  public:
    /// Bow forces below this (N) are raised to it for the contact size (a -> 0 would make C -> 0).
    static constexpr double kMinimumBowForce = 1e-3;

    /// Off the audio thread (allocates): fits the stationary-side SOE for `geometry` at its reference
    /// force and time step 1/sampleRate, then reset(). The stationary side is taken to be a rosin-like
    /// half-space with the same material as the layer (reference §2.3.1, set B).
    void prepare(const ContactGeometry& geometry, const ThermalMaterial& material, double sampleRate);
    /// prepare() for the bowing-rig contact of `contact`.
    void prepare(const ContactParameters& contact, double sampleRate)
    {
        prepare(contact.rig, contact.material, sampleRate);
    }
    /// Ambient: T = 0, no stored heat in the stationary side. Never allocates.
    void reset() noexcept;

    /// Temperature rise (K) this step would reach with frictional power `powerW` (W), sliding speed
    /// `slidingSpeed` (m/s, sign ignored) and normal force `bowForce` (N), without committing. O(1).
    double predict(double powerW, double slidingSpeed, double bowForce) const noexcept;
    /// Advances one time step with these inputs (eq. 2.9). O(M), allocation-free. A non-finite result
    /// resets the state to ambient.
    void commit(double powerW, double slidingSpeed, double bowForce) noexcept;
    /// Committed contact temperature rise above ambient, K.
    double temperature() const noexcept { return temperature_; }
    /// Heat flow into the stationary side during the last committed step, W.
    double stationaryFlux() const noexcept { return lastFlux_; }

    /// The model's own steady conductance (W/K) at constant sliding speed and force: advection + moving
    /// conduction + 1 / (scaled discrete steady resistance of the SOE scheme). A time-stepped steady
    /// slide converges to T = P / steadyConductance(v, F) exactly.
    double steadyConductance(double slidingSpeed, double bowForce) const noexcept;
    /// Analytic steady conductance (W/K), reference eq. 2.7 generalised to the force-dependent radius:
    ///   G_ss = rho c w delta v + pi a^2 e sqrt(3 v / (8 a)) + 1 / int G_avg,  int G_avg = 8/(3 pi^2 K a).
    static double steadyConductance(const ContactGeometry& geometry, const ThermalMaterial& material,
                                    double bowForce, double slidingSpeed) noexcept;

    /// The parts of the step's coefficients that depend on the bow force only (contact size). A friction law
    /// asks for them three times per sample at one force (predict, correct, commit), and the contact radius
    /// costs a cube root each time.
    struct ForceTerms
    {
        double force = -1.0; ///< the (clamped) force they were computed for; < 0 before the first use
        double capacityRate = 0.0, advectionPerSpeed = 0.0, movingPerRootSpeed = 0.0;
        double kernelScale = 1.0, invScaledG0 = 0.0;
    };
    /// ForceTerms at one force (clamped to kMinimumBowForce), for engines that advance many contacts of this
    /// model at once (PlasticLanes).
    ForceTerms forceTermsAt(double bowForce) const noexcept { return forceTerms(bowForce); }
    /// r_m = exp(-dt / tau_m) and the weights c_m tau_m (1 - r_m) of the stationary-side history (eq. 2.9).
    const std::vector<double>& decays() const noexcept { return decay_; }
    const std::vector<double>& weights() const noexcept { return weight_; }
    const StationaryKernel& kernel() const noexcept { return kernel_; }
    double timeStep() const noexcept { return dt_; }

  private:
    /// Contact-size dependent coefficients at one force and speed.
    struct Local
    {
        double capacityRate; ///< C / dt, W/K
        double conductance;  ///< G_loc = advection + moving-side conduction, W/K
        double kernelScale;  ///< A_ref / A: multiplies the kernel weights c_m and g0
        double invScaledG0;  ///< 1 / (kernelScale g0), W/K
    };
    const ForceTerms& forceTerms(double bowForce) const noexcept;
    Local local(double slidingSpeed, double bowForce) const noexcept;
    double solveTemperature(double powerW, const Local& l) const noexcept;

    ContactGeometry geometry_;
    ThermalMaterial material_;
    StationaryKernel kernel_;
    std::vector<double> decay_;   ///< r_m = exp(-dt / tau_m)
    std::vector<double> weight_;  ///< c_m tau_m (1 - r_m), K/W at the reference area
    std::vector<double> history_; ///< u_m for the NEXT step, K
    double dt_ = 1.0 / 48000.0;
    double g0_ = 0.0;                   ///< first-step weight at the reference area, K/W
    double stationaryResistance_ = 0.0; ///< discrete steady resistance at the reference area, K/W
    double effusivity_ = 0.0;           ///< e = sqrt(K rho c), W s^1/2 / (m^2 K)
    double temperature_ = 0.0;
    double historySum_ = 0.0; ///< H for the next step, K
    double lastFlux_ = 0.0;
    mutable ForceTerms forceTerms_; ///< a cache: same values for the same force, so const methods may fill it
};

} // namespace rosin::physics
