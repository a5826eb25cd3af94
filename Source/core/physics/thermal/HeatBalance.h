#pragma once
// Single contact temperature of the rosin layer ([Smith2000], as reconstructed in
// [Notes §2.3-2.5] with the correction of §2.3a): heat balance
//     C dT/dt = P - Q_adv - Q_stat - Q_mov                                  ([Notes] eq. 2.4)
// with layer capacity C = rho c pi a^2 delta and advection Q_adv = rho c w delta |dv| T (w = ratio x a) of
// the layer's rosin, and conduction into BOTH neighbouring solids by convolution with the disc Green's
// function ([Smith2000]: "conduction into the two neighbouring solids"), each solid with its own material:
//  * the stationary side (string, wedge) always;
//  * the moving side (rod, bow hair) the same way while the contact sticks; sliding replaces its surface
//    patch, which washes its memory out over ~one contact width (Washout.h). Its fast-sliding limit is the
//    exact high-Peclet conductance of a disc, 0.888 pi a^2 e sqrt(|dv| / a); the old balance used the
//    quasi-steady pi a^2 e sqrt(3 |dv| / (8 a)) instead, 31 % lower, and only while sliding.
// Time marching: implicit (backward Euler) layer, exact-in-time SOE histories (eq. 2.9); stable at any step.
#include <limits>

#include "core/physics/thermal/ConductingSide.h"
#include "core/physics/thermal/ContactParameters.h"

namespace rosin::physics
{

class HeatBalance
{
  public:
    /// Bow forces below this (N) are raised to it for the contact size (a -> 0 would make C -> 0).
    static constexpr double kMinimumBowForce = 1e-3;

    /// Off the audio thread (allocates): fits both solids' SOE for `geometry` at its reference force and
    /// time step 1/sampleRate, then reset().
    void prepare(const ContactGeometry& geometry, const ContactMaterials& materials, double sampleRate);
    /// prepare() for the bowing-rig contact of `contact`.
    void prepare(const ContactParameters& contact, double sampleRate)
    {
        prepare(contact.rig, contact.materials, sampleRate);
    }
    /// Ambient: T = 0, no stored heat in either solid. Never allocates.
    void reset() noexcept;

    /// Temperature rise (K) this step would reach with frictional power `powerW` (W), sliding speed
    /// `slidingSpeed` (m/s, sign ignored) and normal force `bowForce` (N), without committing. O(1).
    double predict(double powerW, double slidingSpeed, double bowForce) const noexcept;
    /// Advances one time step with these inputs (eq. 2.9). O(M), allocation-free. A non-finite result
    /// resets the state to ambient.
    void commit(double powerW, double slidingSpeed, double bowForce) noexcept;
    /// Advances one time step with the bow lifted (no bow force): the contact is open, so no heat is made and
    /// none passes between the solids; each solid's memory decays by conduction alone (nothing slides past
    /// it), and temperature() is the stationary solid's surface temperature where the contact was, which the
    /// next contact starts from. O(M), allocation-free.
    void open() noexcept;
    /// Committed contact temperature rise above ambient, K.
    double temperature() const noexcept { return temperature_; }
    /// Heat flow into the stationary and into the moving solid during the last committed step, W.
    double stationaryFlux() const noexcept { return stationaryFlux_; }
    double movingFlux() const noexcept { return movingFlux_; }

    /// The model's own steady conductance (W/K) at constant sliding speed and force: advection + both
    /// solids' discrete steady conductances. A time-stepped steady slide converges to T = P / this exactly.
    double steadyConductance(double slidingSpeed, double bowForce) const noexcept;
    /// Analytic steady conductance (W/K), [Notes] eq. 2.7 with §2.3a's moving side:
    ///   G_ss = rho c w delta v + 1 / int G_avg,mov e^{-v t / ell} dt + 1 / int G_avg,stat dt,
    /// int G_avg,stat dt = 8 / (3 pi^2 K_stat a), ell = 1.2685 a (Washout.h).
    static double steadyConductance(const ContactGeometry& geometry, const ContactMaterials& materials,
                                    double bowForce, double slidingSpeed) noexcept;

    /// The parts of the step's coefficients that depend on the bow force only (contact size). A friction law
    /// asks for them three times per sample at one force (predict, correct, commit), and the contact radius
    /// costs a root each time.
    struct ForceTerms
    {
        double force = -1.0; ///< the (clamped) force they were computed for; < 0 before the first use
        double capacityRate = 0.0, advectionPerSpeed = 0.0;
        double kernelScale = 1.0;     ///< A_ref / A: scales both kernels' weights and g0
        double invStationaryG0 = 0.0; ///< 1 / (kernelScale g0_stat), W/K
        double invMovingG0 = 0.0;     ///< 1 / (kernelScale g0_mov) at rest, W/K
        double washoutPerSpeed = 0.0; ///< dt / ell, s/m: x = |dv| dt / ell
    };
    /// ForceTerms at one force (clamped to kMinimumBowForce), for engines that advance many contacts of this
    /// model at once (PlasticLanes).
    ForceTerms forceTermsAt(double bowForce) const noexcept { return forceTerms(bowForce); }
    const ConductingSide& stationarySide() const noexcept { return stationary_; }
    const ConductingSide& movingSide() const noexcept { return moving_; }
    double timeStep() const noexcept { return dt_; }

  private:
    /// Coefficients of one step at one force and speed.
    struct Local
    {
        double capacityRate;             ///< C / dt, W/K
        double advection;                ///< rho c w delta |dv|, W/K
        double kernelScale;              ///< A_ref / A
        double invStationary, invMoving; ///< 1 / g0 of each side at this area (and washout), W/K
        double washout;                  ///< s: the moving history's extra decay this step
        double deposit; ///< share of this step's moving-side deposit still under the contact at its end
    };
    const ForceTerms& forceTerms(double bowForce) const noexcept;
    const Local& local(double slidingSpeed, double bowForce) const noexcept;
    double solveTemperature(double powerW, const Local& l) const noexcept;

    ContactGeometry geometry_;
    ContactMaterials materials_;
    ConductingSide stationary_, moving_;
    double dt_ = 1.0 / 48000.0;
    double temperature_ = 0.0;
    double stationaryFlux_ = 0.0, movingFlux_ = 0.0;
    /// Ambient with both histories exactly zero (from reset() until heat first arrives): a step without
    /// power would only multiply zeros, so it is skipped. An unbowed string of an instrument stays here.
    bool atRest_ = true;
    mutable ForceTerms forceTerms_; ///< a cache: same values for the same force, so const methods may fill it
    // local() of the last (speed, force) asked: a law's predictor asks for the previous sample's committed
    // speed, and a sticking sample asks three times for speed 0. A cache, like forceTerms_.
    // NaN: equal to nothing, so the first call computes.
    mutable double localSpeed_ = std::numeric_limits<double>::quiet_NaN(), localForce_ = localSpeed_;
    mutable Local local_{};
};

} // namespace rosin::physics
