// The friction effects beyond the source texts' laws ([Notes §8], the discrepancy workflow's catalog), each
// against an independent expectation: the junction-growth law slips where mu_s0 (1 + G ln(1 + t_h/tau)) says;
// the creeping contact obeys its dashpot exactly and, on an ideal string, reproduces the pre-slip rise of a
// spring k = P / (L beta (1 - beta)) dragged through a dashpot eta; a loss scale s makes the free decay E(t)
// of the string the nominal string's E(s t).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/physics/friction/BreakawayMarginLaw.h"
#include "core/physics/friction/FrictionEffects.h"
#include "core/physics/friction/JunctionGrowthLaw.h"
#include "core/physics/friction/StickingCreepLaw.h"
#include "core/physics/laws/FrictionLawFactory.h"
#include "core/physics/thermal/ThermalContact.h"
#include "core/physics/voice/BowedStringVoice.h"
#include "support/TestLaws.h"

using namespace rosin::physics;

namespace ROSIN_FILE_LOCAL
{

constexpr double kFs = 48000.0;

std::unique_ptr<FrictionLaw> classical()
{
    return makeFrictionLaw(FrictionModel::Classical, ContactParameters{});
}

TEST(JunctionGrowth, SlipsAtTheAgedStaticLimit)
{
    const double G = 0.15, tau = 0.004, L = 1.1, N = 1.0, rate = 40.0; // force ramp, N/s
    JunctionGrowthLaw law(classical(), G, tau);
    law.prepare(kFs);
    const double mu0 = classical()->staticCoefficient(N);
    // Rigid-sticking force f = L |dvh| rises at `rate`; the contact holds while f <= mu0 N g(t).
    int slip = -1;
    for (int k = 0; k < static_cast<int>(kFs) && slip < 0; ++k)
        if (!law.solve({-rate * (k + 1) / kFs / L, L, N}).sticking)
            slip = k;
    ASSERT_GT(slip, 0);
    // Analytic crossing of rate t = mu0 N (1 + G ln(1 + t / tau)), by bisection.
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200; ++i)
    {
        const double t = 0.5 * (lo + hi);
        (rate * t < mu0 * N * (1.0 + G * std::log1p(t / tau)) ? lo : hi) = t;
    }
    // Sample k carries force rate (k + 1) / fs and has been held for k samples.
    const double expected = lo * kFs - 1.0;
    std::printf("[figure] junction growth: slip at sample %d, expected %.2f (mu_s %.4f -> %.4f)\n", slip,
                expected, mu0, rate * lo / N);
    EXPECT_NEAR(slip, expected, 1.5);
    EXPECT_GT(rate * lo / N, 1.25 * mu0); // the test really ages the contact
}

TEST(JunctionGrowth, ASlipErasesTheMemory)
{
    JunctionGrowthLaw law(classical(), 0.2, 0.002);
    law.prepare(kFs);
    for (int k = 0; k < 960; ++k)
        law.solve({0.0, 1.0, 1.0}); // held 20 ms
    EXPECT_NEAR(law.growthFactor(), 1.0 + 0.2 * std::log1p(0.02 / 0.002), 1e-3);
    law.solve({-10.0, 1.0, 1.0}); // far beyond any static limit: slides
    EXPECT_DOUBLE_EQ(law.growthFactor(), 1.0);
}

// The saturating form (one of the effect's signature families): 1 + G (1 - e^{-t/tau}) at one hold time, and
// a long hold stays below 1 + G where the logarithmic form has gone past it.
TEST(JunctionGrowth, SaturatingFormApproachesItsLimit)
{
    JunctionGrowthLaw law(classical(), 0.2, 0.002, AgeingForm::Saturating);
    law.prepare(kFs);
    for (int k = 0; k < 96; ++k)
        law.solve({0.0, 1.0, 1.0}); // held 2 ms = tau
    EXPECT_NEAR(law.growthFactor(), 1.0 + 0.2 * (1.0 - std::exp(-1.0)), 1e-3);
    for (int k = 0; k < 4800; ++k)
        law.solve({0.0, 1.0, 1.0});             // and 100 ms more
    EXPECT_NEAR(law.growthFactor(), 1.2, 1e-6); // where the logarithmic form would be at 1.79
}

// The first slip from rest comes at (1 + margin) times the law's static limit (a ramp of the rigid-sticking
// force, as in SlipsAtTheAgedStaticLimit); after it the contact holds only the law's own limit, and
// reset() restores the margin.
int firstSlipOfRamp(FrictionLaw& law, double rate, double N)
{
    for (int k = 0; k < static_cast<int>(kFs); ++k)
        if (!law.solve({-rate * (k + 1) / kFs, 1.0, N}).sticking)
            return k;
    return -1;
}

TEST(BreakawayMargin, TheFirstSlipReleasesTheMarginAndOnlyTheFirst)
{
    const double m = 0.3, N = 1.0, rate = 40.0;
    BreakawayMarginLaw law(classical(), m);
    law.prepare(kFs);
    const double mu0 = classical()->staticCoefficient(N);
    ASSERT_TRUE(law.restingLimit(N).has_value());
    EXPECT_NEAR(*law.restingLimit(N), (1.0 + m) * mu0 * N, 1e-9);
    // Sample k carries force rate (k + 1) / fs: the slip is the first sample above the raised limit.
    const double expected = (1.0 + m) * mu0 * N * kFs / rate - 1.0;
    const int first = firstSlipOfRamp(law, rate, N);
    EXPECT_NEAR(first, expected, 1.0);
    EXPECT_TRUE(law.released());
    EXPECT_NEAR(law.staticCoefficient(N), mu0, 1e-12);
    for (int k = 0; k < 480; ++k)
        law.solve({0.0, 1.0, N}); // stuck again, 10 ms
    const int second = firstSlipOfRamp(law, rate, N);
    EXPECT_NEAR(second, mu0 * N * kFs / rate - 1.0, 1.0); // the plain limit: no margin came back
    law.reset();
    EXPECT_FALSE(law.released());
    EXPECT_NEAR(firstSlipOfRamp(law, rate, N), expected, 1.0);
}

// Both held-contact effects refuse what they cannot be, naming themselves.
TEST(HeldContact, ImpossibleSettingsAreRefusedByName)
{
    auto refusal = [](auto make)
    {
        try
        {
            make();
        }
        catch (const std::invalid_argument& e)
        {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(refusal([] { JunctionGrowthLaw(nullptr, 0.1, 0.01); }).find("JunctionGrowthLaw"),
              std::string::npos);
    EXPECT_NE(refusal([] { JunctionGrowthLaw(classical(), -0.1, 0.01); }).find("growth"), std::string::npos);
    EXPECT_NE(refusal([] { BreakawayMarginLaw(nullptr, 0.1); }).find("BreakawayMarginLaw"),
              std::string::npos);
    EXPECT_NE(refusal([] { BreakawayMarginLaw(classical(), -0.1); }).find("margin"), std::string::npos);
}

TEST(BreakawayMargin, IsAFrictionEffectAnyLawCanTake)
{
    FrictionEffects effects;
    EXPECT_FALSE(effects.any());
    effects.breakawayMargin = 0.25;
    EXPECT_TRUE(effects.any());
    auto law = withEffects(classical(), effects);
    law->prepare(kFs);
    EXPECT_NEAR(law->staticCoefficient(1.0), 1.25 * classical()->staticCoefficient(1.0), 1e-12);
}

TEST(StickingCreep, FollowsTheDashpotWhileStuckAndTheLawWhileSliding)
{
    const double eta = 50.0, L = 1.2;
    StickingCreepLaw law(classical(), eta);
    law.prepare(kFs);
    const auto stuck = law.solve({-0.01, L, 1.0});
    EXPECT_TRUE(stuck.sticking);
    EXPECT_NEAR(stuck.dv, L * -0.01 / (L + eta), 1e-15);
    EXPECT_NEAR(stuck.frictionForce, L * (stuck.dv + 0.01), 1e-15); // on the load line
    EXPECT_NEAR(stuck.frictionForce, -eta * stuck.dv, 1e-15);       // and on the dashpot
    auto plain = classical();
    plain->prepare(kFs);
    const auto reference = plain->solve({-5.0, L, 1.0});
    StickingCreepLaw fresh(classical(), eta);
    fresh.prepare(kFs);
    const auto sliding = fresh.solve({-5.0, L, 1.0});
    EXPECT_FALSE(sliding.sticking);
    EXPECT_DOUBLE_EQ(sliding.dv, reference.dv);
    EXPECT_DOUBLE_EQ(sliding.frictionForce, reference.frictionForce);
}

// Energy conservation: the work the dashpot takes from the string, |f dv| = f^2 / eta per second, enters the
// thermal law's contact as heat, exactly as a second contact given the same solutions heats up; and it
// matters: at eta 60 N s/m the held contact warms by kelvins before the first slip of a 10 N/s ramp.
TEST(StickingCreep, TheCreepsWorkHeatsTheContactAsSlidingWould)
{
    const double eta = 60.0, L = 1.2, N = 1.0, rate = 10.0; // force ramp, N/s
    StickingCreepLaw law(makeFrictionLaw(FrictionModel::Plastic, ContactParameters{}), eta);
    law.prepare(kFs);
    ThermalContact reference{ContactParameters{}};
    reference.prepare(kFs, CalibrationQuantity::YieldStress);
    double work = 0.0, worst = 0.0;
    int held = 0;
    for (int k = 0; k < static_cast<int>(kFs); ++k)
    {
        const JunctionInput in{-rate * (k + 1) / kFs / L, L, N};
        const JunctionSolution s = law.solve(in);
        if (!s.sticking)
            break;
        ++held;
        reference.commit(s, N);
        work += std::abs(s.frictionForce * s.dv) / kFs;
        worst = std::max(worst, std::abs(law.contactTemperature() - reference.temperature()));
    }
    std::printf(
        "[figure] creep at %g N s/m: held %d samples, creep work %.3g mJ, contact %.3g K at the slip\n", eta,
        held, 1e3 * work, law.contactTemperature());
    ASSERT_GT(held, 100);
    EXPECT_LT(worst, 1e-12);
    EXPECT_GT(law.contactTemperature(), 1.0);
}

TEST(StickingCreep, PreSlipRiseIsASpringDraggedThroughADashpot)
{
    // Ideal string (no torsion, no bending stiffness, rigid bridge), Guettler's gesture v_b = a t.
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.torsion = false;
    cfg.bendingStiffness = false;
    const double eta = 60.0, a = 1.0, N = 2.0, beta = 0.0899;
    BowedStringVoice voice;
    voice.prepare(cfg, withEffects(classical(), {0.0, 0.005, eta}), kFs);
    const auto& s = cfg.string;
    const double k = s.tension / (s.length * beta * (1.0 - beta)); // string stiffness at the bow
    const double lambda = k / eta;
    double worst = 0.0, shortfall = 0.0;
    int checked = 0;
    for (int n = 0; n < static_cast<int>(0.2 * kFs); ++n)
    {
        const double t = n / kFs;
        const auto out = voice.step({N, a * t, beta, 1.0});
        if (!out.sticking)
            break;
        // y' = a t - (k / eta) y  ->  y = (a / lambda) (t - (1 - e^{-lambda t}) / lambda).
        const double y = a / lambda * (t - (1.0 - std::exp(-lambda * t)) / lambda);
        const double expected = s.tension * y / (beta * s.length);
        if (t > 0.01) // after the string's response to the start of the acceleration has settled
        {
            worst = std::max(worst, std::abs(out.bridgeForce / expected - 1.0));
            shortfall = 1.0 - expected / (s.tension * a * t * t / 2.0 / (beta * s.length));
            ++checked;
        }
    }
    std::printf("[figure] creep: pre-slip bridge force vs spring-dashpot, worst %.2f %% over %d samples; "
                "shortfall against rigid sticking at the end %.1f %%\n",
                100.0 * worst, checked, 100.0 * shortfall);
    EXPECT_GT(checked, 500);
    EXPECT_LT(worst, 0.01);
    EXPECT_GT(shortfall, 0.2); // creep matters here: the rigid parabola would be far off
}

double energyAfter(double lossScale, double seconds)
{
    VoiceConfig cfg;
    cfg.string = stringFromCatalogue("cello-D3");
    cfg.torsion = false;
    cfg.lossScale = lossScale;
    std::vector<double> pulse(48, 0.0);
    for (double& f : pulse)
        f = 0.5;
    BowedStringVoice voice;
    voice.prepare(cfg, std::make_unique<rosin::test::PrescribedForceLaw>(pulse), kFs);
    const int n = static_cast<int>(std::lround(seconds * kFs));
    for (int i = 0; i < n; ++i)
        voice.step({0.0, 0.0, 0.0899, 1.0});
    return voice.storedEnergy();
}

TEST(LossScale, ScalesTheDecayTime)
{
    // Every mode decays at sigma_n proportional to its loss factor, so E_s(t) = E_1(s t) for free decay.
    for (const double scale : {2.0, 3.0})
    {
        const double t = 0.25;
        const double scaled = energyAfter(scale, t), nominal = energyAfter(1.0, scale * t);
        std::printf("[figure] loss scale %.0f: E(%.2f s) = %.4e J vs nominal E(%.2f s) = %.4e J (%+.2f %%)\n",
                    scale, t, scaled, scale * t, nominal, 100.0 * (scaled / nominal - 1.0));
        EXPECT_NEAR(scaled / nominal, 1.0, 0.02);
    }
}

} // namespace ROSIN_FILE_LOCAL
