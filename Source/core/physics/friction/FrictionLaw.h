#pragma once
// The one interface every friction law of the source texts implements. A law is asked, once per sample, which
// friction force and sliding speed are consistent with the string's "load line" ([Notes §1.3.1]):
//
//     f = 2Z (dv - dvHistory),   dv = v - v_b,
//
// where dvHistory is the sliding speed the string would have if the friction force were zero this
// sample, and 2Z = 1/y0 is the inverse of the string's instantaneous bow-point admittance.
// The law returns the intersection with its own characteristic, advancing any internal state
// (hysteresis flag, contact temperature) by one sample.

#include <optional>

namespace rosin::physics
{

/// What the junction knows before the friction force is chosen.
struct JunctionInput
{
    double dvHistory = 0.0; ///< m/s, v_h - v_b: sliding speed with zero friction force this sample
    double loadSlope = 1.0; ///< kg/s, 2Z = 1/y0 (> 0)
    double bowForce = 0.0;  ///< N, normal bow force F_b (>= 0)
};

/// The friction law's answer for this sample.
struct JunctionSolution
{
    double dv = 0.0;            ///< m/s, sliding speed v - v_b
    double frictionForce = 0.0; ///< N, force of the bow on the string (opposes dv)
    bool sticking = true;       ///< true when the string moves with the bow (dv == 0)
};

/// A contact that creeps while the law holds it (StickingCreepLaw): a sticking solution becomes the
/// intersection of the load line with a dashpot of resistance eta (N s/m) in series,
///     dv = 2Z dv_h / (2Z + eta),   f = -eta dv;
/// a sliding one, or any with eta <= 0 (no creep), is returned as it is.
inline JunctionSolution creepingSolution(const JunctionSolution& s, const JunctionInput& in,
                                         double eta) noexcept
{
    if (!s.sticking || !(eta > 0.0))
        return s;
    JunctionSolution c = s;
    c.dv = in.loadSlope * in.dvHistory / (in.loadSlope + eta);
    c.frictionForce = -eta * c.dv;
    return c;
}

/// Base of every friction law. prepare() may allocate and calibrate (never on the audio thread);
/// reset() clears dynamic state without allocating; solve() is real-time safe.
class FrictionLaw
{
  public:
    virtual ~FrictionLaw() = default;
    /// Off the audio thread: compute sample-rate constants, tables, calibrations.
    virtual void prepare(double sampleRate) = 0;
    /// Clear dynamic state (temperature to ambient, stuck). Never allocates.
    virtual void reset() noexcept = 0;
    /// One sample of the junction; advances the law's state.
    virtual JunctionSolution solve(const JunctionInput& in) noexcept = 0;
    /// One sample with a contact that creeps while held (StickingCreepLaw, eta > 0 in N s/m): as solve(),
    /// each sticking solution replaced by creepingSolution. A law whose state follows the power it
    /// dissipates (the thermal laws) overrides this so that the creep's work, |f dv| = f^2 / eta, heats its
    /// contact as sliding does: the energy the dashpot takes from the string has to go somewhere.
    virtual JunctionSolution solveCreeping(const JunctionInput& in, double eta) noexcept
    {
        return creepingSolution(solve(in), in, eta);
    }
    /// Contact temperature rise above ambient, K (0 for laws without a temperature).
    virtual double contactTemperature() const noexcept { return 0.0; }
    /// Limiting static friction coefficient the law would give now (for analysis and tests).
    virtual double staticCoefficient(double bowForce) const noexcept = 0;
    /// For a law whose sticking is exact (dv = 0, f = -2Z dv_h while |2Z dv_h| <= the limit) and leaves its
    /// state as reset() does: the largest force it holds at rest at this bow force, N. Empty otherwise
    /// (state that evolves while stuck, creep, no sticking at all). Scans use it to skip sticking starts
    /// (RampStart.h).
    virtual std::optional<double> restingLimit(double /*bowForce*/) const noexcept { return std::nullopt; }
    /// Short stable identifier, e.g. "classical".
    virtual const char* name() const noexcept = 0;
};

} // namespace rosin::physics
