// Modified thermal friction law (seed 002 eqs. 6-13; reference §3).
#include "ModifiedThermalLaw.h"

#include <algorithm>
#include <cmath>

namespace rosin::physics
{

ModifiedThermalLaw::ModifiedThermalLaw(const ContactParameters& contact, Variant variant)
    : contact_(contact), variant_(variant), jump_(variant == Variant::Bow ? bowJumpCurve() : rodJumpCurve())
{
}

void ModifiedThermalLaw::prepare(double sampleRate)
{
    heat_.prepare(contact_, sampleRate);
    table_.build(contact_, sampleRate,
                 variant_ == Variant::Bow ? CalibrationQuantity::ModifiedBow
                                          : CalibrationQuantity::ModifiedRod);
    prepared_ = true;
    reset();
}

void ModifiedThermalLaw::reset() noexcept
{
    heat_.reset();
    memory_ = {};
    previousPower_ = 0.0;
    previousSpeed_ = 0.0;
}

double ModifiedThermalLaw::strengthFactor(double T) const noexcept
{
    return table_.lookup(T + contact_.ambientOffset);
}

double ModifiedThermalLaw::hertzFactor(double bowForce) const noexcept
{
    if (contact_.rig.scaling != ContactScaling::Hertz)
        return 1.0;
    const double Fb = std::max(bowForce, HeatBalance::kMinimumBowForce);
    return std::cbrt(contact_.rig.referenceForce / Fb); // (Fb / N_ref)^(-1/3)
}

PowerLawCurve ModifiedThermalLaw::curveAt(double T, double bowForce) const noexcept
{
    return {jump_.c, jump_.x0, strengthFactor(T) * hertzFactor(bowForce)};
}

double ModifiedThermalLaw::staticCoefficient(double bowForce) const noexcept
{
    return curveAt(heat_.temperature(), bowForce).mu(0.0);
}

JunctionSolution ModifiedThermalLaw::solve(const JunctionInput& in) noexcept
{
    JunctionInput safe = in;
    safe.dvHistory = std::isfinite(in.dvHistory) ? in.dvHistory : 0.0;
    safe.bowForce = std::isfinite(in.bowForce) ? std::max(in.bowForce, 0.0) : 0.0;
    if (!prepared_)
        return {safe.dvHistory, 0.0, false};
    const double Fb = safe.bowForce;
    const double Tpred = heat_.predict(previousPower_, previousSpeed_, Fb);
    CurveJunctionMemory trial = memory_; // the predictor must not advance the hysteresis state
    JunctionSolution s = solveCurveJunction(curveAt(Tpred, Fb), safe, trial);
    const double Tcorr = heat_.predict(std::abs(s.frictionForce * s.dv), std::abs(s.dv), Fb);
    s = solveCurveJunction(curveAt(Tcorr, Fb), safe, memory_);
    previousPower_ = std::abs(s.frictionForce * s.dv);
    previousSpeed_ = std::abs(s.dv);
    heat_.commit(previousPower_, previousSpeed_, Fb);
    return s;
}

} // namespace rosin::physics
