#pragma once
// The per-sample algebra around the bow junction, written once for every engine that advances a voice:
// BowedStringVoice (alone on its body, or on a body shared with other strings) and VoiceLanes (eight copies,
// lane by lane). From the string's and the body's histories it gives the load line's history v_h, so that
// the friction law solves f on v = v_h + y0 f, and, with f, the string's force on the bridge
// (Resources/docs/physics.md, "The model"; [Notes §1.1] and §5.1). The coefficients are the voice's discrete
// system at its bow position (BowedStringVoice.cpp, updateWeights).
namespace rosin::physics
{

/// What one sample of the junction reads: the outputs of the state before this sample's input.
struct JunctionHistories
{
    double Sv = 0.0, Sa = 0.0, Tv = 0.0; ///< string: bow-point velocity, bridge-force sum, torsional velocity
    double u = 0.0, ud = 0.0, udd = 0.0; ///< body at the bridge: displacement, velocity, acceleration
    double previousFriction = 0.0;       ///< f of the last sample (the band correction's memory)
};

struct JunctionTerms
{
    double beta = 0.1;             ///< bow position
    double tensionPerLength = 0.0; ///< P / L, N/m
    double M3 = 0.0, D = 1.0, A1 = 0.0, Bv = 0.0;
    double U0 = 0.0, U1 = 0.0, U2 = 0.0; ///< the body's direct (instantaneous) answer to a bridge force
    double y0 = 1.0;             ///< instantaneous bow-point admittance, s/kg (band correction included)
    double bandCorrection = 0.0; ///< c of the full-band correction c (1 - z^-1), s/kg
    double bridgeCoupling = 0.0; ///< c in F = R - c G

    /// v_h: the bow-point velocity this sample without friction. G0: the other strings' force on the bridge
    /// this sample, as predicted by their owner (0 for a string alone on its body).
    double loadLineHistory(const JunctionHistories& h, double G0) const noexcept
    {
        const double uE = h.u + U0 * G0, udE = h.ud + U1 * G0, uddE = h.udd + U2 * G0;
        const double Fh = (-tensionPerLength * uE - M3 * uddE - h.Sa) / D;
        return h.Sv + h.Tv - Bv * (uddE + U2 * Fh) + (1.0 - beta) * (udE + U1 * Fh) -
               bandCorrection * h.previousFriction;
    }
    /// R for friction force f: the string's force on the bridge is F = R - c G once the total bridge force G
    /// of this sample is known (G = R / (1 + c) for a string alone on its body).
    double bridgeForceBeforeCoupling(double f, const JunctionHistories& h) const noexcept
    {
        return (1.0 - beta - A1) * f - tensionPerLength * h.u - M3 * h.udd - h.Sa;
    }
};

} // namespace rosin::physics
