#pragma once
// Heat conduction from the contact disc into one of the two solids that touch it (the stationary one, and the
// moving one while it sticks; [Notes §2.3a]): the disc-average Green's function of a half-space and its
// sum-of-exponentials (SOE) approximation. [Notes §2.3.1] (eq. 2.5) and §2.5 (eqs. 2.8-2.9); script soe.py.
#include <vector>

namespace rosin::physics
{

/// G_avg(t) of a uniformly heated disc on a half-space and an SOE fit G(t) ~ sum_m c_m exp(-t / tau_m).
/// fit() allocates (call off the audio thread); every const accessor is allocation-free.
class ConductionKernel
{
  public:
    struct FitOptions
    {
        /// Number of exponentials M; 0: the fewest (from minimumTerms up) whose largest relative error on
        /// [dt, maxTime] is at most maxRelativeError.
        int terms = 0;
        double maxRelativeError = 5e-4; ///< half the kernel's stated accuracy, 1e-3 (a margin for rounding)
        int minimumTerms = 2, startTerms = 20, maximumTerms = 64; ///< the search's bounds and first count
        /// s, end of the fitted interval [dt, maxTime]: longer than any held note. Beyond it only the
        /// kernel's integral is kept (the steady-resistance row), not its t^-3/2 shape.
        double maxTime = 100.0;
        int pointsPerDecade = 40;    ///< collocation density in log t
        double tauBelowDt = 0.3;     ///< smallest tau = tauBelowDt * dt
        double tauAboveMax = 5.0;    ///< largest tau = tauAboveMax * maxTime (carries the t^-3/2 tail)
        double integralWeight = 1e3; ///< weight of the steady-resistance row (see fit())
    };

    /// Contact-average surface temperature rise (K) per joule deposited at t = 0 uniformly over a disc of
    /// radius a (m) on a half-space of conductivity K (W/m/K) and volumetric heat capacity rho c (J/m^3/K):
    ///   G_avg(t) = [1 - e^-u (I0(u) + I1(u))] / (pi a^2 rho c sqrt(pi kappa t)),  u = a^2 / (2 kappa t),
    /// kappa = K / (rho c). [Notes] eq. 2.5 [D]. Units K/J; t in s (> 0).
    static double green(double timeS, double radiusM, double conductivity,
                        double volumetricHeatCapacity) noexcept;

    /// int_0^inf G_avg dt = 8 / (3 pi^2 K a), K/W: mean temperature of a uniformly heated disc per watt
    /// ([Notes §2.3.1], classical result).
    static double steadyResistance(double radiusM, double conductivity) noexcept;

    /// int_0^inf G_avg(t) exp(-t / washoutTime) dt, K/W: the steady resistance of a surface whose heated
    /// patch is carried away after ~washoutTime (the moving side while sliding; [Notes §2.3a]). Simpson in
    /// ln t. washoutTime <= 0 or infinite gives steadyResistance().
    static double washedOutResistance(double radiusM, double conductivity, double volumetricHeatCapacity,
                                      double washoutTime) noexcept;

    /// int_t0^t1 G_avg dt (K/W) by composite Simpson in s = sqrt(t), which removes the t^-1/2 singularity.
    static double integrateGreen(double t0, double t1, double radiusM, double conductivity,
                                 double volumetricHeatCapacity, int intervals = 4000) noexcept;

    /// Non-negative weighted least-squares fit (relative error, Lawson-Hanson NNLS) of the SOE to G_avg on
    /// [dt, maxTime], log-spaced tau in [tauBelowDt dt, tauAboveMax maxTime], with the fewest terms that
    /// keep FitOptions::maxRelativeError (terms NNLS leaves at zero are dropped). One extra row asks that the
    /// scheme's discrete steady resistance g0 + sum c_m tau_m exp(-dt/tau_m) equal 8/(3 pi^2 K a), so the
    /// time-stepped steady state matches eq. 2.7. Also computes the first-step weight g0 = int_0^dt G. A fit
    /// with the same inputs as an earlier one in this process is copied from it (a lock and a map look-up).
    void fit(double radiusM, double conductivity, double volumetricHeatCapacity, double timeStepS,
             const FitOptions& options);
    void fit(double radiusM, double conductivity, double volumetricHeatCapacity, double timeStepS)
    {
        fit(radiusM, conductivity, volumetricHeatCapacity, timeStepS, FitOptions{});
    }

    int size() const noexcept { return static_cast<int>(tau_.size()); }
    const std::vector<double>& coefficients() const noexcept { return c_; }    ///< c_m, K/J
    const std::vector<double>& timeConstants() const noexcept { return tau_; } ///< tau_m, s
    double timeStep() const noexcept { return dt_; }
    double radius() const noexcept { return radius_; }

    /// SOE value sum_m c_m exp(-t/tau_m), K/J.
    double evaluate(double timeS) const noexcept;
    /// First-step weight g0 = int_0^dt G_avg dt (exact quadrature, not the SOE), K/W.
    double firstStepWeight() const noexcept { return g0_; }
    /// Integral of the SOE over [0, inf): sum_m c_m tau_m, K/W.
    double integral() const noexcept;
    /// Steady resistance of the time-stepping scheme (2.9): g0 + sum_m c_m tau_m exp(-dt/tau_m), K/W.
    double discreteSteadyResistance() const noexcept;
    /// Largest |SOE/G_avg - 1| on a log grid (100 points per decade) over [t0, t1].
    double maxRelativeError(double t0, double t1) const noexcept;

  private:
    void fitUncached(double radiusM, double conductivity, double volumetricHeatCapacity, double timeStepS,
                     const FitOptions& options);
    void fitTerms(double radiusM, double conductivity, double volumetricHeatCapacity, double timeStepS,
                  const FitOptions& options, int terms);

    std::vector<double> c_, tau_;
    double g0_ = 0.0, dt_ = 0.0, radius_ = 0.0, conductivity_ = 0.0, heatCapacity_ = 0.0;
};

} // namespace rosin::physics
