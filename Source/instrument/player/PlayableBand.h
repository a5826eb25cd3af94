#pragma once
// Where one string speaks: Schelleng's band of bow forces in which Helmholtz motion is sustained ([Notes §6],
// [Schelleng1973]), for that string's impedance, losses and friction law, at any bow speed and position.
//   F_max = 2 Z0 v_b / (beta (mu_s - mu_d))                 (eq. 6.2)
//   F_min = Z0^2 v_b G / (2 beta^2 (mu_s - mu_d))           (eq. 6.3, Raman's, with G the conductance that
//                                                            stands for the body's and the string's losses)
// The engine fills one per string when it builds the instrument (off the audio thread): Z0 and G from the
// string and body (engine::schellengConductance), mu_s and mu_d from the friction law as the lab's theory
// takes them (scan::frictionLimits). The musical mapping places the bow force inside it (DynamicsPath.h).
// Plain arithmetic: allocation-free and noexcept.

namespace rosin::player
{

/// The model's band as `rosin scan schelleng` measures it (the cello-plastic program, its D3 string on the
/// cello body, 16 forces 0.01-8 N x 6 betas 0.05-0.2, 0.6 s trials, fitted boundaries; Resources/docs/
/// playing.md, "The playable band", gives the table and the commands): the lower edge lies 6.5-20 times
/// above Raman's F_min at 0.02-0.2 m/s (the formula's losses leave out the friction law's own), the upper
/// 0.3-0.86 times Schelleng's F_max (0.5 at 0.05-0.1 m/s, where most playing is; the thermal law closes
/// the band above about 0.3 m/s). Calibrations, measured on that one string and used for every string.
inline constexpr double kMeasuredLowerEdge = 1.0;
inline constexpr double kMeasuredUpperEdge = 0.5;

struct PlayableBand
{
    double Z0 = 0.0;          ///< transverse impedance sqrt(T m), kg/s
    double conductance = 0.0; ///< G, s/kg
    double muStatic = 1.2;    ///< the classical curve's, [Galluzzo2017] eq. 1
    double muDynamic = 0.35;
    /// What the lab measures of the model's own band against the two formulas (a calibration, see
    /// kMeasuredLowerEdge): the edges used are lowerEdge x F_min and upperEdge x F_max.
    double lowerEdge = 1.0, upperEdge = 1.0;
    /// P Z0 of the open string (its period times Z0 = twice its mass), kg: Guettler's wedge scales with it.
    double periodTimesZ0 = 0.0;

    /// Z0 > 0, G >= 0 and mu_s > mu_d >= 0.
    bool valid() const noexcept;
    double deltaMu() const noexcept { return muStatic - muDynamic; }
    /// Schelleng's maximum force at bow speed |v_b| (m/s) and bow position beta, N.
    double maximumForce(double bowSpeed, double beta) const noexcept;
    /// Schelleng's minimum force, N.
    double minimumForce(double bowSpeed, double beta) const noexcept;
    /// The force at `placement` p inside the corrected band on a log scale: F_lo^(1-p) F_hi^p with F_lo =
    /// lowerEdge F_min, F_hi = upperEdge F_max (p = 0 at the lower edge, 1 at the upper; beyond 1 is above
    /// the band, scratch). Where the band has closed (F_min >= F_max, a very small
    /// beta far from the bridge's losses), the two meet at their geometric mean.
    double placedForce(double bowSpeed, double beta, double placement) const noexcept;
    /// A place w in Guettler's wedge of clean starts at beta, per newton of bow force, on a string stopped
    /// at `finger` (P Z0 scales with the vibrating length), m/s^2 per N ([Guettler2002], [Notes §6] eq.
    /// 6.6): a_low^(1-w) a_up^w, so a start from rest at a = F x this lies inside the wedge for 0 <= w <= 1.
    /// 0 for an invalid band.
    double attackAccelerationPerNewton(double beta, double finger, double w = 0.5) const noexcept;
};

} // namespace rosin::player
