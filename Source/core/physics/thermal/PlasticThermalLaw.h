#pragma once
// "Plastic" thermal friction law: the shear yield stress of a softened rosin layer depends on the single
// contact temperature only ([Smith2000] eq. 4; [Galluzzo2017] §2 and Table 2; [Notes §2.1-2.2]):
//     f = -A(Fb) tau_y(T) sgn(dv)  (sliding),   |f| <= A(Fb) tau_y(T)  (sticking),
// with A(Fb) the bowing rig's contact area (Coulomb: A ~ Fb, so mu(T) = tau_y(T) A / Fb depends on T
// alone). tau_y(T) is calibrated on the steady-sliding rig (ThermalCalibration::YieldStress), so at ambient
// the limiting static coefficient is 1.2 (A_rig/Fb)/(A_cal/F_cal) = 0.90 for the Galluzzo contact
// ([Notes §2.1], from [Galluzzo2017] Fig. 14).
#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/thermal/ThermalContact.h"

namespace rosin::physics
{

class PlasticThermalLaw final : public FrictionLaw
{
  public:
    explicit PlasticThermalLaw(const ContactParameters& contact) : thermal_(contact) {}

    /// Off the audio thread: fits the heat model (rig contact) and calibrates tau_y(T) at this rate.
    void prepare(double sampleRate) override;
    void reset() noexcept override;
    /// Per sample ([Notes §0.2], §2.5): T_pred from the previous power and speed; exact solve of the
    /// monotone stick/slide characteristic (eq. 2.3); one corrector pass with the new power; commit.
    /// The corrector is one fixed-point pass: its gain F v |dmu/dT| / (C/dt + G_loc + 1/g0) is < 0.2 at
    /// audio rates but approaches 1 near 0.1 m/s at 100 Hz, where a steady slide can lock onto a
    /// two-cycle. Run at >= 1 kHz.
    JunctionSolution solve(const JunctionInput& in) noexcept override;
    /// As solve(), the held contact creeping (FrictionLaw::solveCreeping): its work heats the contact.
    JunctionSolution solveCreeping(const JunctionInput& in, double eta) noexcept override;
    double contactTemperature() const noexcept override { return thermal_.temperature(); }
    /// tau_y(T) A(Fb) / Fb at the committed temperature (Fb raised to HeatBalance::kMinimumBowForce).
    double staticCoefficient(double bowForce) const noexcept override;
    const char* name() const noexcept override { return "plastic"; }

    /// tau_y (Pa) at contact temperature rise T (K); the table is read at T + ambientOffset.
    double yieldStress(double temperatureRise) const noexcept;
    /// Largest friction force (N) the contact can hold at rise T and normal force Fb: tau_y(T) pi a(Fb)^2.
    double frictionLimit(double temperatureRise, double bowForce) const noexcept;
    /// Exact intersection of the load line f = 2Z (dv - dvh) with the characteristic "vertical segment
    /// |f| <= limit at dv = 0, horizontal lines f = -/+ limit" ([Notes] eq. 2.3). One solution always.
    static JunctionSolution solveCharacteristic(double dvHistory, double loadSlope, double limitN) noexcept;

    const HeatBalance& heat() const noexcept { return thermal_.heat(); }
    const ThermalCalibration& calibration() const noexcept { return thermal_.calibration(); }
    const ContactParameters& contact() const noexcept { return thermal_.contact(); }

  private:
    /// solve() with creepResistance 0 (none), solveCreeping() with eta.
    JunctionSolution step(const JunctionInput& in, double creepResistance) noexcept;

    ThermalContact thermal_;
};

} // namespace rosin::physics
