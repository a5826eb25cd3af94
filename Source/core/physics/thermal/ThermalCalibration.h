#pragma once
// Temperature-dependent material functions of the thermal friction laws, calibrated so that steady
// sliding on the CALIBRATION rig ([Galluzzo2017] Table 2: 500 um at 3 N, 10 um layer) reproduces a measured
// steady-sliding curve ([Notes §2.4], §3.2; [Smith2000] "requiring ... reproduce the measured
// steady-sliding behaviour").
//
// Steady map: T_ss(v) = F_cal mu(v) v / G_ss(v) on a log grid of v in [kMinSpeed, kMaxSpeed], where G_ss
// is the heat model's OWN steady conductance (HeatBalance::steadyConductance, i.e. the discrete SOE
// scheme at the same time step), so that a time-stepped steady slide converges to the curve exactly.
// Inverting T_ss gives v(T) and hence:
//   YieldStress:  tau_y(T) = F_cal mu_classical(v) / A_cal               (Pa; [Smith2000] eq. 4)
//   Viscosity:    eta(T)   = F_cal mu_classical(v) delta_cal / (A_cal v)  (Pa s; [Smith2000] eq. 3)
//   ModifiedBow:  K Y(T)   = mu_steady(v) / h_bow(v)                      ([Woodhouse-thermal] eqs. 9, 11,
//   12) ModifiedRod:  K Y(T)   = mu_steady(v) / h_rod(v)                      ([Woodhouse-thermal] eqs. 9,
//   11, 13)
// (the modified laws use T_ss computed with mu_steady, [Woodhouse-thermal] eq. 9).
//
// Monotone range: T_ss must increase with v to be invertible. If it has a maximum (mu_steady with an
// advection term peaks near 0.3-1 m/s; [Notes §2.4] "Caution"), the table stops at the maximum.
// Lookup clamps: T <= 0 gives the ambient value; above the table's top the top value is held.
// Between T = 0 and the first grid temperature the value is interpolated linearly in T (yield stress,
// K Y) or held at the first grid value (viscosity, which would diverge like 1/T: creep below kMinSpeed is
// not modelled). Elsewhere: linear interpolation of ln(value) in ln T, which preserves monotonicity.
#include <vector>

#include "core/physics/thermal/ContactParameters.h"

namespace rosin::physics
{

enum class CalibrationQuantity
{
    YieldStress, ///< tau_y(T), Pa (plastic law)
    Viscosity,   ///< eta(T), Pa s (viscous law)
    ModifiedBow, ///< K Y(T) with the bow jump curve h (modified law)
    ModifiedRod  ///< K Y(T) with the rod jump curve h (modified law)
};

class ThermalCalibration
{
  public:
    static constexpr double kMinSpeed = 1e-7;   ///< m/s, bottom of the steady map grid
    static constexpr double kMaxSpeed = 10.0;   ///< m/s, top of the steady map grid
    static constexpr int kPointsPerDecade = 50; ///< grid density in log v

    /// Off the audio thread (allocates): builds the table for `quantity` on contact.calibration with the
    /// heat model at `sampleRate` (the rate of the law that will use it).
    void build(const ContactParameters& contact, double sampleRate, CalibrationQuantity quantity);

    /// The calibrated quantity at temperature rise T (K), allocation-free, O(log n).
    double lookup(double temperatureRise) const noexcept;

    /// Steady-sliding target curve of the quantity: mu_classical (plastic, viscous) or mu_steady (modified).
    static double targetMu(CalibrationQuantity quantity, double speed) noexcept;
    /// Jump curve h(v) of the modified law ([Woodhouse-thermal] eqs. 12-13); 1 for the other quantities.
    static double jumpCurve(CalibrationQuantity quantity, double speed) noexcept;

    double ambientValue() const noexcept { return ambientValue_; }
    /// Highest tabulated temperature (K) and its sliding speed (m/s): the top of the monotone range.
    double maxTemperature() const noexcept { return logT_.empty() ? 0.0 : temperatures_.back(); }
    double maxSpeed() const noexcept { return speeds_.empty() ? 0.0 : speeds_.back(); }
    /// True when T_ss(v) reached a maximum below kMaxSpeed and the table was cut there.
    bool truncated() const noexcept { return truncated_; }
    const std::vector<double>& speeds() const noexcept { return speeds_; }             ///< m/s
    const std::vector<double>& temperatures() const noexcept { return temperatures_; } ///< K
    const std::vector<double>& values() const noexcept { return values_; }
    CalibrationQuantity quantity() const noexcept { return quantity_; }

    /// The uniform grid lookup() reads between its first cell and its top, for engines that read it for many
    /// contacts at once (PlasticLanes): lookup(T) = v[i] + f (v[i+1] - v[i]) with x = T / step, i = floor(x),
    /// f = x - i, for 1 <= x < size - 1 (exp of that when isLog).
    struct UniformGrid
    {
        const double* values = nullptr;
        int size = 0;
        double step = 1.0;
        bool isLog = false;
    };
    UniformGrid uniformGrid() const noexcept
    {
        return {uniform_.data(), static_cast<int>(uniform_.size()), uniformStep_, uniformIsLog_};
    }

  private:
    CalibrationQuantity quantity_ = CalibrationQuantity::YieldStress;
    std::vector<double> speeds_, temperatures_, values_, logT_, logValue_;
    // The same table resampled on a uniform temperature grid, so the per-sample lookup is one multiply and a
    // linear interpolation (the viscosity, which spans nine decades, is stored and interpolated as a log).
    std::vector<double> uniform_;
    double uniformStep_ = 1.0;
    bool uniformIsLog_ = false;
    double lookupLogLog(double T) const noexcept;
    double ambientValue_ = 0.0;
    bool truncated_ = false;
};

} // namespace rosin::physics
