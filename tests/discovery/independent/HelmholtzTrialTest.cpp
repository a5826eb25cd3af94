// A full trial of the independent generator against the ideal Helmholtz motion (reference §6.1, seed 001):
// bowed at beta = 0.1 with 0.5 N at a steady 0.1 m/s (inside Schelleng's limits for the cello D string), the
// string settles into one slip per period, slipping for a fraction ~beta of the period 2L/c. And the first
// slip of a Guettler start comes at the static coefficient 0.90 of the Galluzzo rig (reference §2.1), after
// the parabolic pre-slip rise of seed 002 eqs. 3-5, f = P y / (L beta (1 - beta)), y = a t^2 / 2 (with the
// torsional stiffness in series).
#include <gtest/gtest.h>

#include <cmath>

#include "IndependentFixtures.h"

namespace rosin::discovery
{
namespace
{

TEST(IndependentTrial, SteadyBowingReachesHelmholtzMotion)
{
    IndependentTrialSimulator sim(test::nominalRig(), test::kRate);
    const TrialTrace& t = sim.run({0.1, 0.5, Steady{0.1}, 0.6});
    const auto s = physics::stringFromCatalogue("cello-D3");
    const double period = 2.0 * s.length / s.waveSpeed();
    const auto from = static_cast<std::size_t>(0.35 * test::kRate);
    // Slip episodes (reference §7.2); runs shorter than 0.1 ms (1.5 % of a period) are sticking ripple, not
    // the Helmholtz slip, and are counted apart.
    const auto minimum = static_cast<std::size_t>(1e-4 * test::kRate);
    std::vector<double> onsets;
    std::size_t slipping = 0, ripples = 0, start = 0;
    for (std::size_t i = from; i < t.sticking.size(); ++i)
    {
        slipping += t.sticking[i] ? 0 : 1;
        if (t.sticking[i - 1] && !t.sticking[i])
            start = i;
        if (!t.sticking[i - 1] && t.sticking[i] && start > 0)
        {
            if (i - start >= minimum)
                onsets.push_back(static_cast<double>(start) / test::kRate);
            else
                ++ripples;
        }
    }
    const double window = static_cast<double>(t.sticking.size() - from) / test::kRate;
    const double slipFraction = static_cast<double>(slipping) / static_cast<double>(t.sticking.size() - from);
    const double meanPeriod = (onsets.back() - onsets.front()) / static_cast<double>(onsets.size() - 1);
    double worst = 0.0;
    for (std::size_t k = 1; k < onsets.size(); ++k)
        worst = std::max(worst, std::abs(onsets[k] - onsets[k - 1] - period) / period);
    std::printf(
        "Helmholtz: %zu slips (+%zu ripples) in %.3f s (%.1f periods), slip fraction %.4f (beta 0.1), "
        "period %.3f ms vs 2L/c %.3f ms (%.2f %%), worst interval off by %.2f %%\n",
        onsets.size(), ripples, window, window / period, slipFraction, meanPeriod * 1e3, period * 1e3,
        100.0 * (meanPeriod / period - 1.0), 100.0 * worst);
    EXPECT_NEAR(static_cast<double>(onsets.size()), window / period, 1.0); // one slip per period
    EXPECT_NEAR(slipFraction, 0.1, 0.04);
    EXPECT_LE(ripples, onsets.size() / 4);
    EXPECT_NEAR(meanPeriod / period, 1.0, 0.015);
    EXPECT_LT(worst, 0.05);
}

TEST(IndependentTrial, FirstSlipAtTheRigsStaticCoefficientAfterTheParabolicRise)
{
    IndependentTrialSimulator sim(test::nominalRig(), test::kRate);
    const double beta = 0.0899, force = 1.0, accel = 0.5;
    const TrialTrace& t = sim.run(test::guettler(beta, force, accel, 0.3));
    const std::size_t slip = test::firstSlip(t);
    ASSERT_LT(slip, t.sticking.size());
    const double peak = test::peakFriction(t, slip + 1);
    std::printf("first slip at %.4f s with |f| = %.4f N (0.90 Fb expected)\n", slip / test::kRate, peak);
    EXPECT_NEAR(peak / force, 0.90, 0.02);
    // Pre-slip: the friction at half the slip time against the quasi-static parabola.
    const auto s = physics::stringFromCatalogue("cello-D3");
    const std::size_t half = slip / 2;
    const double time = static_cast<double>(half) / test::kRate;
    const double y = 0.5 * accel * time * time;
    // Transverse stiffness P / (L beta (1 - beta)) in series with the torsional one, Z_t c_t / (...): the
    // stuck surface's displacement is shared between bending the string and twisting it.
    const double quasiStatic = y / (s.length * beta * (1.0 - beta)) /
                               (1.0 / s.tension + 1.0 / (s.torsionalImpedance * s.torsionalWaveSpeed));
    std::printf("pre-slip at %.4f s: |f| = %.4f N, parabola %.4f N\n", time, std::abs(t.frictionForce[half]),
                quasiStatic);
    EXPECT_NEAR(std::abs(t.frictionForce[half]) / quasiStatic, 1.0, 0.05);
}

} // namespace
} // namespace rosin::discovery
