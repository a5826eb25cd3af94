#pragma once
// Sliding replaces the moving solid's surface patch under the contact ([Notes §2.3a]): material that has
// passed through carries its heat away and fresh material arrives at ambient, so the moving side's
// conduction memory decays by exp(-|dv| t / ell) on top of diffusion (a lumped form of plug flow).
// The washout length ell follows from the fast-sliding limit of the same lumped model, solved exactly: a disc
// at one temperature T over a half-space sliding at high Peclet number. Each chord c(y) = 2 sqrt(a^2 - y^2)
// of material meets a 1-D half-space held at T for c/v and takes 2 e T sqrt(c v / pi) per unit width, so
// the disc takes G = A e sqrt(v / a) x 2 sqrt(2) B(1/2, 5/4) / pi^(3/2) = 0.8879 A e sqrt(v / a).
// The exponential washout's limit is A e sqrt(v / ell) (int_0^inf e^{-v t / ell} / sqrt(pi t) dt =
// sqrt(ell / v)), so ell = a / 0.8879^2 = 1.2685 a: about one contact width (2a), as §2.3a says.
// ([Notes §2.3]'s quasi-steady pi a^2 e sqrt(3 v / (8 a)), quoted from WG25 via a secondary source and
// argued from a penetration depth, is 31 % below this exact limit;
// tests/core/physics/thermal/WashoutTest.cpp.) Both functions take x = |dv| dt / ell, the share of a washout
// length slid in one time step; they are shared by HeatBalance and PlasticLanes so that a lane and a voice
// step identically.
#include <cmath>

namespace rosin::physics::washout
{

/// ell / a.
inline constexpr double kLengthPerRadius = 1.2685;

/// Below this x the three functions are their series (the small x of audio-rate steps).
inline constexpr double kSeriesLimit = 0.25;

// The series, for a double or a vector of doubles (GCC's vector extension): PlasticLanes evaluates the same
// expressions lane-wise, so that a lane and a voice step identically.
template <typename X> [[gnu::always_inline]] inline X decaySeries(X x) noexcept
{
    return 1.0 - x * (1.0 - x * (0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0 - x * (1.0 / 120.0 - x / 720.0)))));
}
template <typename X> [[gnu::always_inline]] inline X depositSeries(X x) noexcept
{
    return 1.0 - x * (0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0 - x * (1.0 / 120.0 - x / 720.0))));
}
template <typename X> [[gnu::always_inline]] inline X firstStepSeries(X x) noexcept
{
    return 1.0 - x * (1.0 / 3.0 - x * (1.0 / 10.0 - x * (1.0 / 42.0 - x * (1.0 / 216.0 - x / 1320.0))));
}

/// exp(-x): what is left of the moving side's history after one step. A polynomial for the small x of
/// audio-rate steps (error < 2e-8 below x = 0.25), the exponential beyond.
inline double decay(double x) noexcept
{
    if (x < kSeriesLimit)
        return decaySeries(x);
    return std::exp(-x);
}

/// (1 - e^{-x}) / x: the share of this step's deposit that is still under the contact at the step's end, for
/// the history's slow terms (tau_m >> dt; exact in time for them: int_0^dt e^{-v t / ell} dt / dt). Without
/// it a 1 kHz step would put 3 % more heat in the moving side than the continuous model does.
inline double depositFactor(double x) noexcept
{
    if (x < kSeriesLimit)
        return depositSeries(x);
    return -std::expm1(-x) / x;
}

/// The first-step weight's factor int_0^dt t^-1/2 e^{-x t/dt} dt / int_0^dt t^-1/2 dt
/// = sqrt(pi / (4 x)) erf(sqrt(x)) = sum_k (-x)^k / (k! (2k + 1)): the heat put in this step is washed out
/// within it too (1-D kernel, exact at t << a^2/kappa). Series below x = 0.25 (error < 3e-8).
inline double firstStepFactor(double x) noexcept
{
    if (x < kSeriesLimit)
        return firstStepSeries(x);
    const double r = std::sqrt(x);
    return 0.886226925452758 * std::erf(r) / r; // sqrt(pi) / 2
}

} // namespace rosin::physics::washout
