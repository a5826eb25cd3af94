// mu_s and the jump at the first slip of a constant-acceleration trial ([Galluzzo2017] Figs. 15-16), from a
// synthetic bridge force with known values, through 0.3 % noise and a 0.5 Hz sensor high-pass.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/analysis/FirstSlip.h"
#include "core/analysis/Signals.h"

using namespace rosin::analysis;

namespace ROSIN_FILE_LOCAL
{
constexpr double kFs = 48000.0;
constexpr double kPeriod = 1.0 / 146.8; // s

struct Trial
{
    std::vector<double> force;
    double slipTime = 0.0; ///< s, at the bow
};

// The pre-slip parabola F = mu_s (1-beta) N (t/t1)^2 reaches the static limit at t1; the bridge hears of the
// slip a travel time beta P / 2 later and until then follows the same parabola; there the force falls by
// jump * N at once and a Helmholtz sawtooth of amplitude A follows (rising A per period, flyback A).
Trial syntheticTrial(double muS, double jump, double N, double beta, double t1, double A = 1.0)
{
    Trial trial;
    trial.slipTime = t1;
    const double c = muS * (1.0 - beta) * N / (t1 * t1);
    const double tFall = t1 + 0.5 * beta * kPeriod;
    const double before = c * tFall * tFall;
    const double after = before - jump * N;
    const auto n = static_cast<std::size_t>(0.2 * kFs);
    for (std::size_t k = 0; k < n; ++k)
    {
        const double t = static_cast<double>(k) / kFs;
        if (t < tFall)
            trial.force.push_back(c * t * t);
        else
        {
            const double phase = std::fmod((t - tFall) / kPeriod, 1.0);
            trial.force.push_back(after + A * phase);
        }
    }
    return trial;
}

FirstSlipOptions options(double beta, double N, double highPass)
{
    FirstSlipOptions o;
    o.sampleRate = kFs;
    o.beta = beta;
    o.bowForce = N;
    o.periodSeconds = kPeriod;
    o.highPassCutoffHz = highPass;
    return o;
}

TEST(FirstSlip, SyntheticTrialThroughNoiseAndHighPass)
{
    struct Case
    {
        double muS, jump, N, beta, t1;
    };
    // [Galluzzo2017]'s measured average mu_s 0.66 and the classical curve's 1.2; small and large jumps.
    for (const Case c : {Case{0.66, 0.30, 1.0, 0.0899, 0.030}, Case{1.2, 0.8, 1.73, 0.0899, 0.045},
                         Case{0.66, 0.12, 0.84, 0.0357, 0.020}, Case{0.9, 0.5, 2.0, 0.18, 0.060}})
    {
        const auto trial = syntheticTrial(c.muS, c.jump, c.N, c.beta, c.t1);
        const auto y = test::measured(trial.force, 0.003, 0.5, kFs);
        const auto r = firstSlipFromBridgeForce(y, options(c.beta, c.N, 0.5));
        ASSERT_TRUE(r.found);
        EXPECT_NEAR(r.muStatic / c.muS, 1.0, 0.02);
        EXPECT_NEAR(r.jump / c.jump, 1.0, 0.05);
        EXPECT_NEAR(r.firstSlipTime, c.t1, 2.0 / kFs);
        std::printf(
            "[figure] first slip, synthetic mu_s %.2f jump %.2f (N %.2f, beta %.4f): measured mu_s %.4f "
            "(%.2f %%), jump %.4f (%.2f %%), t1 %.5f s (true %.5f)\n",
            c.muS, c.jump, c.N, c.beta, r.muStatic, 100.0 * (r.muStatic / c.muS - 1.0), r.jump,
            100.0 * (r.jump / c.jump - 1.0), r.firstSlipTime, c.t1);
    }
}

// Without undoing the sensor's high-pass, the 0.5 Hz roll-off lowers a 45 ms parabola by ~omega_c t / 3
// (~4.7 %); without the travel-time correction the force is read where the bridge hears the slip (the
// seed's "force just before the first slip"), (1 + beta P / (2 t1))^2 higher.
TEST(FirstSlip, HighPassAndTravelTimeMatter)
{
    const double muS = 1.2, jump = 0.8, N = 1.0, beta = 0.0899, t1 = 0.045;
    const auto trial = syntheticTrial(muS, jump, N, beta, t1);
    const auto y = test::measured(trial.force, 0.003, 0.5, kFs);
    const auto undone = firstSlipFromBridgeForce(y, options(beta, N, 0.5));
    const auto ignored = firstSlipFromBridgeForce(y, options(beta, N, 0.0));
    auto atBridge = options(beta, N, 0.5);
    atBridge.travelTimeCorrection = false;
    const auto seedStyle = firstSlipFromBridgeForce(y, atBridge);
    ASSERT_TRUE(undone.found && ignored.found && seedStyle.found);
    const double lowered = 2.0 * M_PI * 0.5 * t1 / 3.0;
    EXPECT_NEAR(ignored.muStatic / undone.muStatic, 1.0 - lowered, 0.01);
    const double late = std::pow(1.0 + 0.5 * beta * kPeriod / t1, 2);
    EXPECT_NEAR(seedStyle.muStatic / undone.muStatic, late, 0.003);
    std::printf("[figure] first slip mu_s: HP undone %.4f, HP ignored %.4f (expected -%.2f %%), read at the "
                "bridge %.4f (expected +%.2f %%)\n",
                undone.muStatic, ignored.muStatic, 100.0 * lowered, seedStyle.muStatic, 100.0 * (late - 1.0));
}

TEST(FirstSlip, HighPassInverseIsExactForItsDiscretisation)
{
    // y[n] = a (y[n-1] + x[n] - x[n-1]), a = 1 / (1 + omega_c / fs): the backward-Euler high-pass.
    const double fc = 0.5, a = 1.0 / (1.0 + 2.0 * M_PI * fc / kFs);
    std::vector<double> x(4800), y(4800);
    double yPrev = 0.0, xPrev = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k)
    {
        x[k] = std::sin(0.01 * static_cast<double>(k)) + 1e-4 * static_cast<double>(k);
        y[k] = yPrev = a * (yPrev + x[k] - xPrev);
        xPrev = x[k];
    }
    const auto back = undoFirstOrderHighPass(y, fc, kFs);
    double worst = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k)
        worst = std::max(worst, std::abs(back[k] - x[k]));
    EXPECT_LT(worst, 1e-9);
}

} // namespace ROSIN_FILE_LOCAL
