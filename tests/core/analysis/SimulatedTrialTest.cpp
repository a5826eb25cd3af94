// The lab on the simulation itself: the cello D3 string on the cello body with the classical friction curve.
//  * A Guettler trial (N = 1 N, a = 1 m/s^2, beta = 0.0899): mu_s and the jump from the bridge force alone,
//    with 0.3 % noise and a 0.5 Hz sensor high-pass, against the solver's own first slip.
//  * Steady bowing inside Schelleng's limits (0.3 N, 0.05 m/s, beta 0.1; see HelmholtzMotionTest): labelled
//    Helmholtz from the state and from the noisy, high-passed force alone.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "core/analysis/FirstSlip.h"
#include "core/analysis/RegimeClassifier.h"
#include "core/analysis/Signals.h"
#include "core/analysis/SlipOnsets.h"
#include "core/analysis/TransientLength.h"
#include "core/physics/friction/CurveFrictionLaw.h"
#include "support/Runs.h"

using namespace rosin;
using namespace rosin::physics;
using namespace rosin::analysis;

namespace ROSIN_FILE_LOCAL
{
constexpr double kFs = 48000.0;

VoiceConfig celloD()
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.body = celloBody();
    return cfg;
}

std::unique_ptr<FrictionLaw> classical()
{
    return std::make_unique<ClassicalFrictionLaw>(ClassicalCurve{}, "classical");
}

void split(const rosin::test::Trace& t, std::vector<double>& force, std::vector<bool>& sticking)
{
    for (const auto& s : t.samples)
    {
        force.push_back(s.bridgeForce);
        sticking.push_back(s.sticking);
    }
}

TEST(SimulatedTrial, FirstSlipFromNoisyForceMatchesTheState)
{
    const auto cfg = celloD();
    const double N = 1.0, a = 1.0, beta = 0.0899;
    const auto trace = rosin::test::bowAccelerating(cfg, classical(), kFs, N, a, beta, 0.3);
    std::vector<double> force;
    std::vector<bool> sticking;
    split(trace, force, sticking);

    FirstSlipOptions o;
    o.sampleRate = kFs;
    o.beta = beta;
    o.bowForce = N;
    o.periodSeconds = 1.0 / cfg.string.fundamental();
    const auto truth = firstSlipFromState(force, sticking, o);
    o.highPassCutoffHz = 0.5;
    const auto measured = firstSlipFromBridgeForce(analysis::test::measured(force, 0.003, 0.5, kFs), o);
    ASSERT_TRUE(truth.found);
    ASSERT_TRUE(measured.found);
    // The curve's static coefficient, reached by the stuck string (PreSlipTest: 1.1993 on a rigid bridge).
    EXPECT_NEAR(truth.muStatic, ClassicalCurve{}.mu(0.0), 0.02 * ClassicalCurve{}.mu(0.0));
    EXPECT_NEAR(measured.muStatic / truth.muStatic, 1.0, 0.02);
    EXPECT_NEAR(measured.jump / truth.jump, 1.0, 0.05);
    EXPECT_NEAR(measured.firstSlipTime, truth.firstSlipTime, 0.1 * o.periodSeconds);
    std::printf(
        "[figure] simulated Guettler trial (classical, body, N 1 N, a 1 m/s^2, beta 0.0899): state mu_s "
        "%.4f jump %.4f t1 %.5f s; noisy force mu_s %.4f (%.2f %%) jump %.4f (%.2f %%) t1 %.5f s\n",
        truth.muStatic, truth.jump, truth.firstSlipTime, measured.muStatic,
        100.0 * (measured.muStatic / truth.muStatic - 1.0), measured.jump,
        100.0 * (measured.jump / truth.jump - 1.0), measured.firstSlipTime);

    // Its transient, from the state (informative: the attack may or may not settle in 0.3 s).
    const double P = kFs / cfg.string.fundamental();
    TransientOptions t;
    t.windowEnd = force.size();
    const auto transient = measureTransient(flybacksOnly(slipEpisodesFromVoice(trace.samples)), P, t);
    char length[32] = "not reached";
    if (transient.periods)
        std::snprintf(length, sizeof length, "%.2f periods", *transient.periods);
    std::printf(
        "[figure] simulated Guettler trial transient (state): %s, failure %s (short %.1f P, long %.1f P)\n",
        length, transientFailureName(transient.failure), transient.shortIntervalPeriods,
        transient.longIntervalPeriods);
}

TEST(SimulatedTrial, SteadyHelmholtzLabelledFromStateAndFromForce)
{
    const auto cfg = celloD();
    const auto trace = rosin::test::bowSteady(cfg, classical(), kFs, 0.3, 0.05, 0.1, 1.5);
    std::vector<double> force;
    std::vector<bool> sticking;
    split(trace, force, sticking);
    const double P = kFs / cfg.string.fundamental();
    const AnalysisWindow window{static_cast<std::size_t>(1.0 * kFs), 0}; // the last 0.5 s, ~73 periods
    const auto state = classifyFromState(sticking, force, P, window);
    const auto fromForce =
        classifyFromBridgeForce(analysis::test::measured(force, 0.003, 0.5, kFs), P, window);
    EXPECT_EQ(classifyFromVoice(trace.samples, P, window).regime, Regime::Helmholtz);
    EXPECT_EQ(state.regime, Regime::Helmholtz);
    EXPECT_EQ(fromForce.regime, Regime::Helmholtz);
    EXPECT_NEAR(state.measuredPeriod / P, fromForce.measuredPeriod / P, 0.002);
    std::printf(
        "[figure] simulated steady bowing 0.3 N 0.05 m/s beta 0.1: state %s (P_m/P %.4f, s %.3f, slip "
        "fraction %.3f), force %s (P_m/P %.4f, s %.3f, autocorrelation %.4f)\n",
        regimeName(state.regime), state.measuredPeriod / P, state.sawtoothness, state.slipFraction,
        regimeName(fromForce.regime), fromForce.measuredPeriod / P, fromForce.sawtoothness,
        fromForce.autocorrelation);
}

// The reconstructed curve in Helmholtz motion (HelmholtzMotionTest: 0.3 N) leaves partial slips, runs of
// sliding in which the string lags the bow without reversing. Counted as slips (the sticking flag alone) they
// make several "slips" per period; counting flybacks (the voice's velocities), or reading the bridge force,
// finds the one flyback per period of Helmholtz motion.
TEST(SimulatedTrial, PartialSlipsAreNotFlybacks)
{
    const auto cfg = celloD();
    const double P = kFs / cfg.string.fundamental();
    const AnalysisWindow window{static_cast<std::size_t>(1.0 * kFs), 0};
    const auto trace = rosin::test::bowSteady(
        cfg, std::make_unique<ReconstructedFrictionLaw>(ReconstructedCurve{}, "reconstructed"), kFs, 0.3,
        0.05, 0.1, 1.5);
    std::vector<double> force;
    std::vector<bool> sticking;
    split(trace, force, sticking);
    const auto everySlip = classifyFromState(sticking, force, P, window);
    const auto flybacks = classifyFromVoice(trace.samples, P, window);
    const auto fromForce =
        classifyFromBridgeForce(analysis::test::measured(force, 0.003, 0.5, kFs), P, window);
    EXPECT_EQ(flybacks.regime, Regime::Helmholtz);
    EXPECT_EQ(fromForce.regime, Regime::Helmholtz);
    EXPECT_NEAR(flybacks.slipsPerPeriod, 1.0, 0.01);
    EXPECT_GT(everySlip.slipsPerPeriod, 1.5);
    std::printf(
        "[figure] simulated reconstructed 0.3 N: every sliding run %s (%.2f slips/P), flybacks %s (%.3f/P, "
        "s %.3f), force alone %s (%.3f/P, s %.3f)\n",
        regimeName(everySlip.regime), everySlip.slipsPerPeriod, regimeName(flybacks.regime),
        flybacks.slipsPerPeriod, flybacks.sawtoothness, regimeName(fromForce.regime),
        fromForce.slipsPerPeriod, fromForce.sawtoothness);
}

// Above Schelleng's maximum force F_max = 2 Z0 v_b / (beta (mu_s - mu_d)) ([Notes] eq. 6.2; 0.64 N here)
// Helmholtz motion cannot last: both routes, state and noisy force alone, must say so, and agree.
TEST(SimulatedTrial, AboveMaximumForceNotHelmholtzByEitherRoute)
{
    const auto cfg = celloD();
    const double P = kFs / cfg.string.fundamental();
    const double vb = 0.05, beta = 0.1;
    const ClassicalCurve curve{};
    const double Fmax = 2.0 * cfg.string.impedance() * vb / (beta * (curve.mu(0.0) - curve.mu(1e3)));
    const double F = 1.6 * Fmax;
    const AnalysisWindow window{static_cast<std::size_t>(1.0 * kFs), 0};
    const auto trace = rosin::test::bowSteady(cfg, classical(), kFs, F, vb, beta, 1.5);
    std::vector<double> force;
    std::vector<bool> sticking;
    split(trace, force, sticking);
    const auto state = classifyFromVoice(trace.samples, P, window);
    const auto fromForce =
        classifyFromBridgeForce(analysis::test::measured(force, 0.003, 0.5, kFs), P, window);
    EXPECT_NE(state.regime, Regime::Helmholtz);
    EXPECT_EQ(state.regime, fromForce.regime);
    std::printf(
        "[figure] simulated steady bowing %.2f N (1.6 F_max, F_max = %.2f N): state %s (slips/P %.3f, cv "
        "%.3f), force %s (slips/P %.3f, cv %.3f)\n",
        F, Fmax, regimeName(state.regime), state.slipsPerPeriod, state.intervalCv,
        regimeName(fromForce.regime), fromForce.slipsPerPeriod, fromForce.intervalCv);
}

// A limit of the force-only route, recorded rather than asserted: at very light force (0.05 N) the body's
// Schelleng ripples are as large as the falls of the slips at the bridge, so the bridge force alone cannot
// count the slips that the state sees (three per period in this model).
TEST(SimulatedTrial, LightForceShowsTheLimitOfTheForceOnlyRoute)
{
    const auto cfg = celloD();
    const double P = kFs / cfg.string.fundamental();
    const AnalysisWindow window{static_cast<std::size_t>(1.0 * kFs), 0};
    const auto trace = rosin::test::bowSteady(cfg, classical(), kFs, 0.05, 0.05, 0.1, 1.5);
    std::vector<double> force;
    std::vector<bool> sticking;
    split(trace, force, sticking);
    const auto state = classifyFromVoice(trace.samples, P, window);
    const auto fromForce =
        classifyFromBridgeForce(analysis::test::measured(force, 0.003, 0.5, kFs), P, window);
    EXPECT_GT(state.slipsPerPeriod, 1.5); // the solver's own record: several slips per period
    std::printf("[figure] simulated steady bowing 0.05 N 0.05 m/s beta 0.1: state %s (slips/P %.3f, k %d), "
                "force alone %s (slips/P %.3f, cv %.3f)\n",
                regimeName(state.regime), state.slipsPerPeriod, state.slipsPerCycle,
                regimeName(fromForce.regime), fromForce.slipsPerPeriod, fromForce.intervalCv);
}

} // namespace ROSIN_FILE_LOCAL
