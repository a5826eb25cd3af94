// Viscous thermal friction law ([Smith2000] eq. 3; [Woodhouse-thermal] eq. 2).
#include "core/physics/thermal/ViscousThermalLaw.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/physics/numeric/BracketedRoot.h"

namespace rosin::physics
{

void ViscousThermalLaw::prepare(double sampleRate)
{
    thermal_.prepare(sampleRate, CalibrationQuantity::Viscosity);
}

void ViscousThermalLaw::reset() noexcept
{
    thermal_.reset();
}

double ViscousThermalLaw::viscosity(double T) const noexcept
{
    return thermal_.property(T);
}

double ViscousThermalLaw::dampingCoefficient(double T, double bowForce) const noexcept
{
    return thermal_.area(bowForce) * viscosity(T) / thermal_.contact().rig.layerThickness;
}

// Load line f = 2Z (dv - dvh) meets f = -c dv at dv = 2Z dvh / (2Z + c).
JunctionSolution ViscousThermalLaw::solveLinear(double dvh, double twoZ, double c) noexcept
{
    const double dv = twoZ * dvh / (twoZ + c);
    return {dv, -c * dv, std::abs(dv) < kStickingSpeed};
}

JunctionSolution ViscousThermalLaw::solve(const JunctionInput& in) noexcept
{
    const double dvh = std::isfinite(in.dvHistory) ? in.dvHistory : 0.0;
    const double Fb = std::isfinite(in.bowForce) ? std::max(in.bowForce, 0.0) : 0.0;
    const double twoZ = in.loadSlope;
    if (!thermal_.prepared())
        return {dvh, 0.0, false};
    if (Fb == 0.0)
    {
        // Bow lifted: zero contact area, so c = 0 at any temperature, and the open contact moves no heat
        // (HeatBalance::open).
        const JunctionSolution s = solveLinear(dvh, twoZ, 0.0);
        thermal_.open();
        return s;
    }
    const HeatBalance& heat = thermal_.heat();
    // g(T) = Phi(P(T)) - T: the temperature this step reaches with the power dissipated at viscosity eta(T),
    // minus T. Phi (HeatBalance::predict) is O(1).
    JunctionSolution s;
    auto residual = [&](double T)
    {
        s = solveLinear(dvh, twoZ, dampingCoefficient(T, Fb));
        return thermal_.predict(s, Fb) - T;
    };
    // Predictor (previous power) and one corrector pass, as for the other thermal laws.
    const double Tpred = thermal_.predict(Fb);
    const double Tcorr = Tpred + residual(Tpred);
    const double g = residual(Tcorr);
    if (std::abs(g) > 1e-3 * (1.0 + Tcorr)) // K
    {
        // The corrector did not settle: eta(T) spans ~9 decades, and with a stiff load line (2Z >> c, e.g.
        // velocity-controlled sliding) the fixed-point gain dPhi/dT >> 1, so plain substitution jumps
        // between a cold and a hot state every sample. Solve g(T) = 0 instead, on a bracket that always
        // holds a root: P ranges over [0, Pmax], Pmax = 2Z dvh^2 / 4 (at c = 2Z).
        double lo = Tcorr, hi = Tcorr, glo = g, ghi = g;
        if (g > 0.0)
        {
            hi = heat.predict(0.25 * twoZ * dvh * dvh, 0.0, Fb); // g(hi) <= 0
            ghi = residual(hi);
        }
        else
        {
            lo = heat.predict(0.0, std::abs(dvh), Fb); // g(lo) >= 0
            glo = residual(lo);
        }
        const double T = illinoisRoot(residual, lo, glo, hi, ghi, Tcorr, {1e-9, 1e-12}, 60);
        residual(T); // leaves s at the solution for T
    }
    thermal_.commit(s, Fb);
    return s;
}

} // namespace rosin::physics
