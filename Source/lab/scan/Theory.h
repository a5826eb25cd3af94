#pragma once
// The idealised playability limits a scan is compared with ([Notes §6]), evaluated for the scan's
// model:
//   Schelleng F_max(beta) = c / beta,    c = 2 Z0 v_b / (mu_s - mu_d)                         (eq. 6.2)
//   F_min(beta) = d / beta^2 from the body's admittance Y (eq. 6.5, small-beta approximation):
//     d = 2 v_b Z0^2 / (pi^2 dmu) max_t [ Re sum Y(n w0)/n^2 - Re sum (-1)^n Y(n w0) e^{i n w0 t}/n^2 ],
//   which for a dashpot Y = 1/R is Raman's Z0^2 v_b / (2 R dmu) (eq. 6.3); the "bridge resistance" reported
//   is the dashpot R that gives the same d. A rigid bridge (Y = 0) gives d = 0 and no R.
//   The same with the model's total losses ([Notes §6.2], "decided"): the body's Y plus the string's own
//   losses as the bridge conductance that would damp each mode alike, G_n = pi n eta_n / (2 Z0) (a bridge of
//   conductance G reflects 1 - 2 Z0 G of a wave, so mode n loses 4 Z0 G f0 of its energy a second, i.e.
//   eta_n = 2 Z0 G / (pi n)). Torsion's losses are not folded in (their place in F_min is not settled: Z0^2
//   -> Z0 Z_eff by Schelleng, less by simulation, [Notes §6.2]). Guettler's wedge a_low < a <= a_up, each
//   proportional to F (eq. 6.6), with P Z0 = 2 x string mass.
// Z0 = sqrt(T m) of the transverse string (torsion not folded in, as in the formulas of [Notes §6]).
// mu_s and mu_d: physics::frictionLimits (core/physics/laws/FrictionLimits.h).
#include <complex>
#include <functional>
#include <optional>
#include <vector>

#include "core/physics/laws/FrictionLimits.h"
#include "core/physics/laws/GuettlerWedge.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

using physics::FrictionLimits;

using physics::GuettlerWedge;

struct Theory
{
    double Z0 = 0.0;                        ///< kg/s
    std::optional<double> bridgeResistance; ///< kg/s, empty for a rigid bridge
    FrictionLimits friction;
    double periodSeconds = 0.0; ///< 1/f0
    double fmaxCoefficient = 0.0;
    double fminCoefficient = 0.0;      ///< eq. 6.5 with the body's admittance, N
    double fminTotalCoefficient = 0.0; ///< eq. 6.5 with the body and the string's own losses, N
    std::vector<GuettlerWedge> wedge;  ///< one per beta of the scan
};

/// mu_s and mu_d of the model's friction law (prepares one law: ~25 ms for a thermal one).
FrictionLimits frictionLimits(const ModelSpec& model, double sampleRate);

/// d of eq. 6.5 for a bridge admittance Y(f) (f in Hz), string fundamental f0, bow speed vb, dmu > 0.
double fminCoefficient(const std::function<std::complex<double>(double)>& admittance, double f0, double Z0,
                       double vb, double dmu);

/// The string's own losses as a bridge conductance at harmonic n, G_n = pi n eta_n / (2 Z0), s/kg.
double stringLossConductance(const physics::StringParameters& string, int n);

using physics::guettlerWedge; // eq. 6.6, core/physics/laws/GuettlerWedge.h

/// Everything above for a scan (Schelleng: v_b = the scan's bow speed; Guettler: one wedge per beta, and the
/// coefficients at v_b = 1 m/s).
Theory scanTheory(const ScanSpec& spec);

} // namespace rosin::scan
