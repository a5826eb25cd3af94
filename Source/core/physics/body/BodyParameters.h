#pragma once
// The instrument body as seen from the string: a driving-point admittance at the bridge notch in the
// bowing direction, written as a sum of modes ([Notes] eq. 5.2):
//     Y(omega) = sum_k i omega / ( m_k (omega_k^2 - omega^2 + i omega omega_k / Q_k) ).
#include <complex>
#include <cstdint>
#include <string>
#include <vector>

namespace rosin::physics
{

struct BodyMode
{
    double frequency = 0.0;     ///< Hz
    double q = 30.0;            ///< quality factor
    double effectiveMass = 1.0; ///< kg, modal mass at the bridge notch
    /// sigma: radiated power / (rho0 c0 S <v^2>), 0 for a mode that does not radiate (BodyRadiation.h).
    double radiationEfficiency = 0.0;
    /// +1 or -1: the sign of the mode's net volume velocity relative to its bridge motion.
    double radiationSign = 1.0;
    /// Factor on the mode's radiated pressure, 1 for the modelled body: a program's radiation gains
    /// (RadiationGains.h), a calibration to one instrument's recording; the admittance does not change.
    double radiationGain = 1.0;
};

/// What the body's radiation depends on besides its modes (BodyRadiation.h).
struct BodyRadiation
{
    double surfaceDensity = 2.0;       ///< rho_s, kg/m^2: mean mass per area of the plates
    double listeningDistance = 1.0;    ///< r, m
    double unityEfficiencyHz = 4200.0; ///< statistical modes radiate with sigma = min(1, f / this)
    double directivityHz = 4000.0;     ///< D(f) = min(2, 1 + f / this)
};

struct BodyParameters
{
    std::string name = "rigid";  ///< "cello", "violin", "rigid", ...
    std::vector<BodyMode> modes; ///< empty means a rigid bridge
    BodyRadiation radiation;
    bool rigid() const { return modes.empty(); }
    /// The modal formula (5.2) evaluated at frequency f (Hz): bridge velocity per unit force, s/kg.
    std::complex<double> admittance(double frequencyHz) const;
};

/// A rigid bridge (no body modes).
BodyParameters rigidBody();
/// Cello body: parametric low "signature" modes ([Notes §5.2]) plus a statistical high-frequency set
/// ([Notes §5.3]), generated deterministically from `seed` up to maxFrequencyHz. Above 1.2 kHz, where the
/// modes overlap, one band mode per 1/12 octave carries their mean admittance (about 90 modes in all);
/// denseModes = true keeps every statistical mode instead (about 650 below 10 kHz).
BodyParameters celloBody(std::uint32_t seed = 1, double maxFrequencyHz = 10000.0, bool denseModes = false);
/// Violin body, built the same way with violin-scaled modes (band modes above 1.5 kHz).
BodyParameters violinBody(std::uint32_t seed = 1, double maxFrequencyHz = 12000.0, bool denseModes = false);
/// By name: "cello", "violin" or "rigid"; throws std::invalid_argument naming the expected values.
BodyParameters bodyByName(const std::string& name);

} // namespace rosin::physics
