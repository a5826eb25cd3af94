#pragma once
// What a measurement of the bowed point itself shows, when a rig records the bow-point velocity and the
// friction force (measurements.md channels bowPointVelocity and frictionForce), over a stretch of steady
// oscillation:
//   * the slip fraction: the share of the time the string slips past the bow, |v - v_b| > 0.5 |v_b| (in
//     ideal Helmholtz motion the string slips at -v_b (1 - beta) / beta, ten times v_b at beta 0.09, and
//     sticks at 0, so the threshold is far from both; ideal Helmholtz motion slips for beta of the period,
//     rounded corners for longer);
//   * the hysteresis loop's area ([Smith2000] Fig. 2c, [Galluzzo2017] Figs. 20-21): the signed area enclosed
//   by the
//     friction coefficient f / N against the sliding speed v - v_b, per period, divided by the mean bow
//     speed so that loops at different speeds compare. A friction curve traces the same path out and back
//     (area 0); a thermal law's friction lags the temperature, so slipping ends at a lower coefficient than
//     it began with. Positive when the loop runs anticlockwise with f taken positive when it opposes the
//     sliding (the sign convention of the recording does not matter).
#include <cstddef>
#include <optional>
#include <vector>

namespace rosin::analysis
{

/// Share of samples [from, to) in which |bowPointVelocity - bowVelocity| > 0.5 |bowVelocity|; nullopt for an
/// empty stretch or a bow at rest throughout.
std::optional<double> slipFraction(const std::vector<double>& bowPointVelocity,
                                   const std::vector<double>& bowVelocity, std::size_t from, std::size_t to);

/// Signed loop area in (v - v_b, f / N) per period over samples [from, to), divided by the mean |v_b|
/// (dimensionless); nullopt for fewer than two periods or a bow at rest.
std::optional<double> normalisedLoopArea(const std::vector<double>& bowPointVelocity,
                                         const std::vector<double>& bowVelocity,
                                         const std::vector<double>& frictionForce, double bowForce,
                                         std::size_t from, std::size_t to, double periodSamples);

} // namespace rosin::analysis
