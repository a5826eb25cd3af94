#pragma once
// Modified ("enhanced") thermal friction law of [Woodhouse-thermal] (eqs. 6-9; [Notes §3]):
//     f = -K Fb h(|dv|) Y(T) sgn(dv),   K Y(T0) = 1,
// with h the jump curve of a real bow (eq. 12) or of a rosin-coated rod (eq. 13). At a fixed temperature
// it is a friction curve PowerLawCurve{c, x0, scale = K Y(T)} and is solved exactly with the hysteresis
// rule (solveCurveJunction), so it can jump at the first slip. K Y(T) is calibrated so steady sliding
// reproduces mu_steady (eq. 11): ThermalCalibration::ModifiedBow / ModifiedRod.
// Hertz contact scaling (A ~ Fb^(2/3), [Notes §8.3]): A = K Fb (Fb/N_ref)^(-1/3), so the force is
// multiplied by (Fb/N_ref)^(-1/3); with Coulomb scaling the factor is 1.
#include "core/physics/friction/CurveJunctionSolver.h"
#include "core/physics/friction/FrictionCurves.h"
#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/thermal/ThermalContact.h"

namespace rosin::physics
{

class ModifiedThermalLaw final : public FrictionLaw
{
  public:
    enum class Variant
    {
        Bow, ///< h(v) = 0.5 (|v| + 0.27)^-0.4 ([Woodhouse-thermal] eq. 12)
        Rod  ///< h(v) = 0.37 (|v| + 0.35)^-0.4 ([Woodhouse-thermal] eq. 13)
    };

    ModifiedThermalLaw(const ContactParameters& contact, Variant variant);

    void prepare(double sampleRate) override;
    void reset() noexcept override;
    /// Predictor (previous power): curve solve with scale K Y(T_pred); corrector with this sample's power
    /// (from the same hysteresis memory); heat commit. As for PlasticThermalLaw, the single corrector pass
    /// needs a sample rate >= 1 kHz; near the top of the calibrated range dKY/dT grows without bound.
    JunctionSolution solve(const JunctionInput& in) noexcept override;
    /// As solve(), the held contact creeping (FrictionLaw::solveCreeping): its work heats the contact.
    JunctionSolution solveCreeping(const JunctionInput& in, double eta) noexcept override;
    double contactTemperature() const noexcept override { return thermal_.temperature(); }
    /// K Y(T) h(0) (x Hertz factor) at the committed temperature; at ambient mu_steady(0) = 0.2 * 0.011^-0.4.
    double staticCoefficient(double bowForce) const noexcept override;
    const char* name() const noexcept override
    {
        return variant_ == Variant::Bow ? "modified-bow" : "modified-rod";
    }

    /// K Y (dimensionless) at contact temperature rise T (K); the table is read at T + ambientOffset.
    double strengthFactor(double temperatureRise) const noexcept;
    /// The friction curve at rise T and normal force Fb: h scaled by K Y(T) and the Hertz factor.
    PowerLawCurve curveAt(double temperatureRise, double bowForce) const noexcept;

    const HeatBalance& heat() const noexcept { return thermal_.heat(); }
    const ThermalCalibration& calibration() const noexcept { return thermal_.calibration(); }
    Variant variant() const noexcept { return variant_; }

  private:
    double hertzFactor(double bowForce) const noexcept;
    /// solve() with creepResistance 0 (none), solveCreeping() with eta.
    JunctionSolution step(const JunctionInput& in, double creepResistance) noexcept;

    ThermalContact thermal_;
    Variant variant_;
    PowerLawCurve jump_;
    CurveJunctionMemory memory_;
};

} // namespace rosin::physics
