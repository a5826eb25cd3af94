// Modified thermal friction law ([Woodhouse-thermal] eqs. 6-13; [Notes §3]).
#include "core/physics/thermal/ModifiedThermalLaw.h"

#include <algorithm>
#include <cmath>

namespace rosin::physics
{

ModifiedThermalLaw::ModifiedThermalLaw(const ContactParameters& contact, Variant variant)
    : thermal_(contact), variant_(variant), jump_(variant == Variant::Bow ? bowJumpCurve() : rodJumpCurve())
{
}

void ModifiedThermalLaw::prepare(double sampleRate)
{
    thermal_.prepare(sampleRate, variant_ == Variant::Bow ? CalibrationQuantity::ModifiedBow
                                                          : CalibrationQuantity::ModifiedRod);
    memory_ = {};
}

void ModifiedThermalLaw::reset() noexcept
{
    thermal_.reset();
    memory_ = {};
}

double ModifiedThermalLaw::strengthFactor(double T) const noexcept
{
    return thermal_.property(T);
}

double ModifiedThermalLaw::hertzFactor(double bowForce) const noexcept
{
    const auto& rig = thermal_.contact().rig;
    if (rig.scaling != ContactScaling::Hertz)
        return 1.0;
    const double Fb = std::max(bowForce, HeatBalance::kMinimumBowForce);
    return std::cbrt(rig.referenceForce / Fb); // (Fb / N_ref)^(-1/3)
}

PowerLawCurve ModifiedThermalLaw::curveAt(double T, double bowForce) const noexcept
{
    return {jump_.c, jump_.x0, strengthFactor(T) * hertzFactor(bowForce)};
}

double ModifiedThermalLaw::staticCoefficient(double bowForce) const noexcept
{
    return curveAt(thermal_.temperature(), bowForce).mu(0.0);
}

JunctionSolution ModifiedThermalLaw::solve(const JunctionInput& in) noexcept
{
    return step(in, 0.0);
}

JunctionSolution ModifiedThermalLaw::solveCreeping(const JunctionInput& in, double eta) noexcept
{
    return step(in, eta);
}

JunctionSolution ModifiedThermalLaw::step(const JunctionInput& in, double creepResistance) noexcept
{
    JunctionInput safe = in;
    safe.dvHistory = std::isfinite(in.dvHistory) ? in.dvHistory : 0.0;
    safe.bowForce = std::isfinite(in.bowForce) ? std::max(in.bowForce, 0.0) : 0.0;
    if (!thermal_.prepared())
        return {safe.dvHistory, 0.0, false};
    const double Fb = safe.bowForce;
    if (Fb == 0.0)
    {
        // Bow lifted: the junction holds at most mu Fb = 0 at any temperature, so both passes below would
        // solve the same junction: one pass (advancing the hysteresis memory once, as the corrector does),
        // and the open contact moves no heat (HeatBalance::open).
        const JunctionSolution s = creepingSolution(
            solveCurveJunction(curveAt(thermal_.temperature(), Fb), safe, memory_), safe, creepResistance);
        thermal_.open();
        return s;
    }
    // A held contact creeps where a creep resistance is given (creepingSolution; 0: none), so the
    // corrector sees the creep's power and the commit takes it.
    CurveJunctionMemory trial = memory_; // the predictor must not advance the hysteresis state
    JunctionSolution s = creepingSolution(solveCurveJunction(curveAt(thermal_.predict(Fb), Fb), safe, trial),
                                          safe, creepResistance);
    s = creepingSolution(solveCurveJunction(curveAt(thermal_.predict(s, Fb), Fb), safe, memory_), safe,
                         creepResistance);
    thermal_.commit(s, Fb);
    return s;
}

} // namespace rosin::physics
