#pragma once
// The musical mapping's bow arm: one dynamics value d (pp 0 .. ff 1) moves bow speed and bow position
// together the way players do (louder: faster and nearer the bridge; Askenfelt's and Schoonderwaldt's
// measurements, summarised in Resources/docs/playing.md), and the bow pressure q places the force inside the
// string's playable band (PlayableBand.h) at p = placement(q): F = F_min^(1-p) F_max^p.
//   v_b = v_pp (v_ff / v_pp)^d,   beta = beta_pp (beta_ff / beta_pp)^d     (log paths)
// beta is the bow's place on the vibrating length: a player keeps the contact point in proportion to the
// stopped length (nearer the bridge in high positions), which keeps the band where it is on a stopped note.
// Plain arithmetic: allocation-free and noexcept.
#include "instrument/player/PlayableBand.h"

namespace rosin::player
{

struct DynamicsPath
{
    // Speeds from the slow end of the literature's range; the top is where the model's thermal contact
    // still sustains Helmholtz motion (the lab's scans close the band above about 0.3 m/s; at 0.35 m/s the
    // string slips most of each period). Helmholtz motion's level goes as v_b / beta, so the path spans
    // 20 log10(12 x 0.22 / 0.05) = 34 dB, a cello's pp-ff range (30-35 dB).
    double speedPp = 0.01, speedFf = 0.12; ///< m/s
    double betaPp = 0.22, betaFf = 0.05;   ///< sul tasto side at pp, near the bridge at ff

    /// Placement p at bow pressure 0 (flautando: the band's lower edge), 0.5 (normal) and 1 (scratch: above
    /// the upper edge). Normal rises from the band's lower half at pp into its upper half at ff, as a
    /// player leans in (LibreStrings' p ~ 0.65 is normal playing); set once, before the playing grid was
    /// measured, and not fitted to it.
    double flautando = 0.0, normalPp = 0.4, normalFf = 0.7, scratch = 1.6;

    double bowSpeed(double dynamics) const noexcept;
    double beta(double dynamics) const noexcept;
    /// p for bow pressure q in 0..1 at dynamics d (piecewise linear through the three placements; the
    /// normal one rises from normalPp to normalFf with d: louder is heavier, not only faster).
    double placement(double bowPressure, double dynamics) const noexcept;
};

/// What the musical mapping asks of one string now.
/// The force range of the musical mapping, N: from a violin's lightest pp (below the host parameter's 0.05
/// N) to a cellist's ff near the bridge on the C string.
inline constexpr double kMusicalForceMin = 0.05, kMusicalForceMax = 8.0;

struct MusicalBow
{
    double bowForce = 0.0, bowSpeed = 0.0, beta = 0.1;
    double upperForce = 0.0; ///< the band's upper edge here, N: an accent stays below it
};

/// The bow for dynamics d and pressure q on a string whose band is `band`; betaFactor scales the path's
/// beta (CC21, MPE slide), within the parameter range. An invalid band gets the classical curve's.
MusicalBow musicalBow(const DynamicsPath& path, const PlayableBand& band, double dynamics, double bowPressure,
                      double betaFactor) noexcept;

} // namespace rosin::player
