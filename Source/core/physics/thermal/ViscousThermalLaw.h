#pragma once
// "Viscous" thermal friction law: a Newtonian rosin layer of thickness delta with temperature-dependent
// viscosity ([Smith2000] eq. 3; [Woodhouse-thermal] eq. 2):
//     f = -(A(Fb) eta(T) / delta_rig) dv = -c dv.
// At fixed T the law is linear, so the load-line solve is closed-form: dv = 2Z dvh / (2Z + c). There is no
// sticking barrier ([Woodhouse-thermal] Fig. 4): the string always creeps, if only at ~1e-8 of dvh when cold.
// eta(T) is calibrated on the steady-sliding rig (ThermalCalibration::Viscosity).
#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/thermal/ThermalContact.h"

namespace rosin::physics
{

class ViscousThermalLaw final : public FrictionLaw
{
  public:
    /// |dv| below this (m/s) is reported as `sticking` (a label only: the law has no static friction).
    /// Equal to the bottom of the calibration grid, below which the viscosity table is held constant.
    static constexpr double kStickingSpeed = ThermalCalibration::kMinSpeed;

    explicit ViscousThermalLaw(const ContactParameters& contact) : thermal_(contact) {}

    void prepare(double sampleRate) override;
    void reset() noexcept override;
    /// Predictor (previous power), linear solve, corrector (this power), linear solve, heat commit. If the
    /// corrector has not settled (|Phi(P(T_corr)) - T_corr| > 1e-3 (1 + T_corr) K: the coupling gain of
    /// this law can be >> 1 because eta(T) spans ~9 decades), the step's temperature is instead found as
    /// the root of T = Phi(P(T)) by bracketed Illinois iteration (<= 60 O(1) evaluations, no allocation).
    JunctionSolution solve(const JunctionInput& in) noexcept override;
    double contactTemperature() const noexcept override { return thermal_.temperature(); }
    /// A viscous layer has no static friction: always 0.
    double staticCoefficient(double) const noexcept override { return 0.0; }
    const char* name() const noexcept override { return "viscous"; }

    /// eta (Pa s) at contact temperature rise T (K); the table is read at T + ambientOffset.
    double viscosity(double temperatureRise) const noexcept;
    /// Damping coefficient c = A(Fb) eta(T) / delta_rig, kg/s.
    double dampingCoefficient(double temperatureRise, double bowForce) const noexcept;

    const HeatBalance& heat() const noexcept { return thermal_.heat(); }
    const ThermalCalibration& calibration() const noexcept { return thermal_.calibration(); }

  private:
    static JunctionSolution solveLinear(double dvh, double twoZ, double c) noexcept;

    ThermalContact thermal_;
};

} // namespace rosin::physics
