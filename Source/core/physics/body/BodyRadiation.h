#pragma once
// From the body's modes to the sound pressure a listener hears (Resources/docs/physics.md; [Notes, sound]).
//
// Each body mode radiates in proportion to its own motion: the admittance and the radiation share the
// body's poles and differ only in their residues ([MSS2017], "Joint modeling of impedance and
// radiation as a recursive parallel filter structure"). The residue of mode k follows from its radiated
// power, W_k = rho0 c0 sigma_k S <v^2>, where S <v^2> = m_k v_b^2 / rho_s (the mode's kinetic energy spread
// over plates of surface density rho_s; m_k is its effective mass at the bridge, v_b its bridge velocity),
// and from the far field of a source of directivity D: <p^2> = D rho0 c0 W / (4 pi r^2). So at distance r
//     |p_k| = (rho0 c0 / r) sqrt(D_k sigma_k m_k / (4 pi rho_s)) |v_b,k|.
// The pressure is taken from the mode's acceleration: a compact source radiates the time derivative of its
// volume velocity (p = rho0 / (4 pi r) dQ/dt), so the bow's static pull on the bridge, and anything below the
// lowest mode, reaches the listener only as the modes' transients. Where the body stops being compact (sigma
// reaches 1) the pressure follows the velocity instead, as a piston's radiation impedance turns from mass to
// resistance: all modes' sum passes one first-order low-pass H(w) = 1 / (1 + i w / w_u) at that frequency,
// and c_k carries |1 + i w_k / w_u| so that each mode keeps the level above at its own resonance. Without
// it a low mode's mass-line acceleration would radiate at full strength up to any frequency.
#include "core/physics/body/BodyParameters.h"

namespace rosin::physics
{

/// Air at 20 C.
inline constexpr double kAirDensity = 1.204;   ///< rho0, kg/m^3
inline constexpr double kSpeedOfSound = 343.2; ///< c0, m/s

/// Radiation efficiency of a statistical (or band) mode at frequency f: sigma = min(1, f / unityHz). Fitted
/// through Bissinger's violin measurements [Bissinger2008] ("Radiation damping, efficiency, and directivity
/// for violin normal modes below 4 kHz", JASA 2008: first corpus bending modes 0.12 +- 0.03 and 0.11 +- 0.04
/// near 500 Hz, rising to ~1 by 4 kHz): unity at 4.2 kHz for the violin. The cello, a violin scaled ~2.1x in
/// length, has the same ka at 1/2.1 the frequency [A]: unity at 2.0 kHz.
double statisticalRadiationEfficiency(const BodyRadiation& radiation, double frequencyHz) noexcept;

/// Directivity toward the listener, D(f) = min(2, 1 + f / directivityHz): Bissinger's averaged directivity
/// rises from ~1 for the lowest modes to ~2 at 4 kHz (violin); the cello's scaled by 2.1 [A].
double directivity(const BodyRadiation& radiation, double frequencyHz) noexcept;

/// c_k: sound pressure at the listener (Pa) per unit bridge acceleration of mode k (m/s^2), signed, before
/// the common low-pass H.
double pressurePerAcceleration(const BodyMode& mode, const BodyRadiation& radiation) noexcept;

/// Share of mode k's losses that leave as sound: eta_rad / eta = W / (omega E) x Q, with
/// eta_rad = rho0 c0 sigma_k / (rho_s omega_k) from the same power. Bissinger measured 31 % +- 10 % for the
/// violin's first corpus bending modes: a check of sigma, rho_s and Q together.
double radiatedShare(const BodyMode& mode, const BodyRadiation& radiation) noexcept;

/// Radiativity p / F (Pa/N) at frequency f from the modal sum: H(omega) sum_k c_k i omega Y_k(omega), Y_k
/// the mode's term of the bridge admittance (BodyParameters::admittance).
std::complex<double> radiativity(const BodyParameters& body, double frequencyHz);

} // namespace rosin::physics
