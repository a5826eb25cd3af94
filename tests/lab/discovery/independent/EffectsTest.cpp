// Every own-form effect changes the features it should, by the amount its form says (analytic expectations
// from the form and the rig's numbers, with margins), against the same trial without it.
#include <gtest/gtest.h>

#include <cmath>

#include "lab/discovery/independent/IndependentFixtures.h"
#include "lab/discovery/independent/YieldStressTable.h"

namespace rosin::discovery
{
namespace ROSIN_FILE_LOCAL
{

constexpr double kBeta = 0.0899;

struct FirstSlip
{
    double time = 0.0;  ///< s
    double force = 0.0; ///< peak |friction| up to and including the first slip, N
    double drop = 0.0;  ///< how far |friction| falls within 0.5 ms after it, N
};

FirstSlip firstSlip(const OwnEffects& effects, double force, double accel)
{
    IndependentTrialSimulator sim(test::nominalRig(effects), test::kRate);
    const TrialTrace& t = sim.run(test::guettler(kBeta, force, accel, 0.35));
    FirstSlip r;
    const std::size_t i = test::firstSlip(t);
    EXPECT_LT(i, t.sticking.size());
    r.time = static_cast<double>(i) / test::kRate;
    r.force = test::peakFriction(t, i + 1);
    double low = r.force;
    for (std::size_t k = i; k < i + static_cast<std::size_t>(5e-4 * test::kRate) && k < t.sticking.size();
         ++k)
        low = std::min(low, std::abs(t.frictionForce[k]));
    r.drop = r.force - low;
    return r;
}

TEST(OwnEffects, JunctionGrowthRaisesTheFirstSlipForceByItsSaturatingGain)
{
    OwnEffects e;
    e.growthGain = 0.4;
    e.growthTime = 0.02;
    const FirstSlip base = firstSlip({}, 1.0, 0.3), aged = firstSlip(e, 1.0, 0.3);
    const double expected = 1.0 + e.growthGain * (1.0 - std::exp(-aged.time / e.growthTime));
    std::printf("junction growth: first slip %.4f N at %.3f s vs %.4f N at %.3f s: x%.3f (form: x%.3f)\n",
                aged.force, aged.time, base.force, base.time, aged.force / base.force, expected);
    EXPECT_NEAR(aged.force / base.force, expected, 0.03);
}

TEST(OwnEffects, ColdBreakawayJumpsAtTheFirstSlip)
{
    OwnEffects e;
    e.breakawayMargin = 0.3;
    e.breakawayWarmth = 4.0;
    const FirstSlip base = firstSlip({}, 1.0, 1.0), cold = firstSlip(e, 1.0, 1.0);
    std::printf("breakaway: first slip %.4f N (base %.4f N), drop within 0.5 ms %.4f N (base %.4f N)\n",
                cold.force, base.force, cold.drop, base.drop);
    EXPECT_NEAR(cold.force / base.force, 1.0 + e.breakawayMargin, 0.03); // the contact is cold (T = 0)
    EXPECT_GT(cold.drop, 0.6 * e.breakawayMargin * base.force);          // released with a jump
    EXPECT_GT(cold.drop, 3.0 * base.drop);
}

TEST(OwnEffects, HertzContactMakesTheStaticCoefficientFallWithForce)
{
    OwnEffects e;
    e.hertz = true;
    e.hertzExponent = 2.0 / 3.0;
    e.hertzReferenceForce = 1.0;
    for (double force : {0.5, 2.0})
    {
        const FirstSlip h = firstSlip(e, force, 1.0);
        const double expected = 0.90 * std::pow(force / e.hertzReferenceForce, e.hertzExponent - 1.0);
        std::printf("hertz: Fb %.1f N: first-slip coefficient %.4f (form: %.4f)\n", force, h.force / force,
                    expected);
        EXPECT_NEAR(h.force / force / expected, 1.0, 0.025);
    }
}

TEST(OwnEffects, StickingCreepLowersThePreSlipForceAndDelaysTheSlip)
{
    OwnEffects e;
    e.creepShare = 0.5;
    e.creepResistance = 20.0;
    IndependentTrialSimulator baseSim(test::nominalRig(), test::kRate),
        creepSim(test::nominalRig(e), test::kRate);
    const TrialTrace base = baseSim.run(test::guettler(kBeta, 1.0, 1.0, 0.3));
    const TrialTrace creep = creepSim.run(test::guettler(kBeta, 1.0, 1.0, 0.3));
    const std::size_t slip = test::firstSlip(base);
    // Below the threshold share nothing creeps (the Bingham form), above it the force lags.
    std::size_t below = 0;
    while (std::abs(base.frictionForce[below]) < 0.4 * 0.9)
        ++below;
    EXPECT_NEAR(creep.frictionForce[below] / base.frictionForce[below], 1.0, 1e-9);
    const std::size_t late = slip - static_cast<std::size_t>(2e-3 * test::kRate);
    const double lag = 1.0 - creep.frictionForce[late] / base.frictionForce[late];
    std::printf("creep: force 2 ms before the base slip lower by %.2f %%, slip at %.4f s vs %.4f s\n",
                100 * lag, test::firstSlip(creep) / test::kRate, slip / test::kRate);
    EXPECT_GT(lag, 0.01);
    EXPECT_GT(test::firstSlip(creep), slip);
}

// Steady-sliding temperature on the calibration rig from the continuous model, written out here.
double calibrationTemperature(double v)
{
    const auto m = physics::galluzzoContact().materials;
    const double a = 500e-6, delta = 10e-6, pi = std::numbers::pi;
    const double G = m.layer.volumetricHeatCapacity * a * delta * v +
                     3.0 * pi * pi / 8.0 * a * (m.stationary.conductivity + m.moving.conductivity) +
                     pi * a * a * m.moving.effusivity() * std::sqrt(v / a);
    return 3.0 * classicalFriction(v) * v / G;
}

TEST(OwnEffects, WarmRosinStartsAtTheCalibratedCoefficientOfItsTemperature)
{
    OwnEffects warm, cold;
    warm.ambientOffset = 12.0;
    cold.ambientOffset = -12.0;
    const FirstSlip base = firstSlip({}, 1.0, 1.0), w = firstSlip(warm, 1.0, 1.0),
                    c = firstSlip(cold, 1.0, 1.0);
    // The speed whose steady temperature is the offset, by bisection in log v.
    double lo = 1e-7, hi = 1.0;
    for (int i = 0; i < 80; ++i)
        (calibrationTemperature(std::sqrt(lo * hi)) < warm.ambientOffset ? lo : hi) = std::sqrt(lo * hi);
    const double expected = 0.75 * classicalFriction(lo); // (a_rig / a_cal)^2 = 0.75 at 1 N
    std::printf("ambient +12 K: first-slip coefficient %.4f (calibration: %.4f); -12 K: %.4f; base %.4f\n",
                w.force, expected, c.force, base.force);
    EXPECT_NEAR(w.force / expected, 1.0, 0.03);
    EXPECT_GT(c.force, 1.03 * base.force);
}

// The viscous law is the same calibration read as a viscosity ([Smith2000] eq. 3): steady sliding on the
// calibration rig, at the steady temperature of the continuous heat model written out above, reproduces the
// classical curve it was calibrated on.
TEST(OwnEffects, ViscousLawSlidesSteadilyOnTheCalibrationCurve)
{
    const YieldStressTable table({500e-6, 3.0, 10e-6}, test::nominalRig().materials, 1.0 / test::kRate);
    const double area = std::numbers::pi * 500e-6 * 500e-6;
    for (double v : {1e-4, 1e-3, 1e-2, 0.1})
    {
        const double mu = area * table.viscosity(calibrationTemperature(v)) * v / 10e-6 / 3.0;
        std::printf("viscous, steady sliding at %g m/s: mu %.4f (classical curve %.4f)\n", v, mu,
                    classicalFriction(v));
        EXPECT_NEAR(mu / classicalFriction(v), 1.0, 0.05);
    }
}

// [Woodhouse-thermal] Fig. 4: a viscous layer has no sticking barrier. From rest the cold contact creeps
// at once, at the rate its viscosity gives on the load line (slip = f layer / (A eta)), where the plastic
// contact is stuck, and it never stops creeping.
TEST(OwnEffects, ViscousLawCreepsFromRestWhereThePlasticLawSticks)
{
    OwnEffects e;
    e.viscous = true;
    const IndependentRig rig = test::nominalRig(e);
    IndependentTrialSimulator viscousSim(rig, test::kRate), plasticSim(test::nominalRig(), test::kRate);
    const TrialTrace viscous = viscousSim.run(test::guettler(kBeta, 1.0, 1.0, 0.3));
    const TrialTrace plastic = plasticSim.run(test::guettler(kBeta, 1.0, 1.0, 0.3));
    const YieldStressTable table(
        {rig.calibration.radius, rig.calibration.normalForce, rig.calibration.layerThickness}, rig.materials,
        1.0 / test::kRate);
    const std::size_t k = test::firstSlip(plastic) / 2;
    const double slip = viscous.bowPointVelocity[k] - viscous.bowVelocity[k];
    const double expected = std::abs(viscous.frictionForce[k]) * rig.layerThickness /
                            (viscousSim.contactArea(1.0) * table.viscosity(0.0));
    std::printf("viscous creep halfway to the plastic first slip: %.3g m/s (load line: %.3g m/s); plastic "
                "%.3g m/s\n",
                std::abs(slip), expected, plastic.bowPointVelocity[k] - plastic.bowVelocity[k]);
    EXPECT_NEAR(std::abs(slip) / expected, 1.0, 0.05);
    EXPECT_EQ(plastic.bowPointVelocity[k] - plastic.bowVelocity[k], 0.0);
    for (std::size_t i = 1; i < viscous.bowVelocity.size(); ++i)
        ASSERT_NE(viscous.bowPointVelocity[i], viscous.bowVelocity[i]) << "stuck at sample " << i;
}

TEST(OwnEffects, BendingLossFactorOnlyDampsHighPartials)
{
    const auto s = physics::stringFromCatalogue("cello-D3");
    const LossLaw nominal =
        stringLossLaw(s.tension, s.massPerLength, s.bendingStiffness, s.etaF(false), s.etaB(), s.etaA());
    const LossLaw raised = stringLossLaw(s.tension, s.massPerLength, s.bendingStiffness, s.etaF(false),
                                         s.etaB(), s.etaA(), 0.0, 4.0);
    const double f0 = s.fundamental();
    EXPECT_NEAR(raised(f0) / nominal(f0), 1.0, 0.01);
    // At the 40th partial the bending term is most of the loss ([Notes §4.1]: Q 810 there).
    EXPECT_GT(raised(40.0 * f0) / nominal(40.0 * f0), 2.5);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::discovery
