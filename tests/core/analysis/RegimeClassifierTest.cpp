// The steady-state labels of [Notes §7.4] on canonical signals whose regime is known by construction,
// through both entry points: the solver's state (sticking flag + bridge force) and the bridge force alone
// (with 0.3 % noise and a 0.5 Hz sensor high-pass).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/analysis/RegimeClassifier.h"
#include "core/analysis/Signals.h"

using namespace rosin::analysis;

namespace ROSIN_FILE_LOCAL
{
constexpr double kFs = 48000.0;
constexpr double kP = kFs / 146.8; // cello D3 nominal period, samples
const auto kLength = static_cast<std::size_t>(0.4 * kFs);
const AnalysisWindow kWindow{static_cast<std::size_t>(0.1 * kFs), 0}; // ~44 periods

struct Both
{
    RegimeAnalysis state, force;
};

Both classifyBoth(const test::Synthetic& s, double P = kP)
{
    return {classifyFromState(s.sticking, s.force, P, kWindow),
            classifyFromBridgeForce(test::measured(s.force, 0.003, 0.5, kFs), P, kWindow)};
}

void print(const char* what, const Both& b)
{
    std::printf("[figure] %s: state -> %s (slips/P %.3f, k %d, P_m/P %.4f, s %.3f, slip fraction %.3f); "
                "force -> %s (slips/P %.3f, k %d, P_m/P %.4f, s %.3f, cv %.3f)\n",
                what, regimeName(b.state.regime), b.state.slipsPerPeriod, b.state.slipsPerCycle,
                b.state.measuredPeriod / kP, b.state.sawtoothness, b.state.slipFraction,
                regimeName(b.force.regime), b.force.slipsPerPeriod, b.force.slipsPerCycle,
                b.force.measuredPeriod / kP, b.force.sawtoothness, b.force.intervalCv);
}

// An ideal sawtooth: one slip per period of length beta P; sawtoothness 1 by its Fourier series.
TEST(RegimeClassifier, SawtoothIsHelmholtz)
{
    const auto s =
        test::stickSlip(kLength, kP, {0.0}, {1.0}, 1.0, static_cast<std::size_t>(0.1 * kP), 11.0, 0.03);
    const auto b = classifyBoth(s);
    print("sawtooth, 1 slip/P", b);
    for (const auto& r : {b.state, b.force})
    {
        EXPECT_EQ(r.regime, Regime::Helmholtz);
        EXPECT_EQ(r.slipsPerCycle, 1);
        EXPECT_NEAR(r.measuredPeriod / kP, 1.0, 0.003);
        EXPECT_NEAR(r.slipsPerPeriod, 1.0, 0.01);
        EXPECT_NEAR(r.sawtoothness, 1.0, 0.05);
        EXPECT_TRUE(r.withinReferencePitch);
    }
    EXPECT_NEAR(b.state.slipFraction, 0.1, 0.005);
}

// A flattened Helmholtz motion (period 6 % long, as near F_max or on a stopped string) is still Helmholtz,
// reported as outside the +-3 % pitch band of [Notes §7.4].
TEST(RegimeClassifier, FlattenedSawtoothIsHelmholtzWithPitchReported)
{
    const auto s = test::stickSlip(kLength, 1.06 * kP, {0.0}, {1.0}, 1.0, static_cast<std::size_t>(0.1 * kP));
    const auto b = classifyBoth(s);
    print("sawtooth 6 % flat", b);
    for (const auto& r : {b.state, b.force})
    {
        EXPECT_EQ(r.regime, Regime::Helmholtz);
        EXPECT_FALSE(r.withinReferencePitch);
        EXPECT_NEAR(r.pitchCents, 1200.0 * std::log2(1.0 / 1.06), 3.0);
    }
}

// One slip per period but a strong second harmonic: a sawtooth -(2/pi) sum sin(n w t)/n plus
// sin(2 w t)/(2 pi) has |F2| halved, so s = (2/pi) / (2 * 1/(2 pi)) = 2: S-motion.
TEST(RegimeClassifier, SecondHarmonicCornerIsSMotion)
{
    auto s = test::stickSlip(kLength, kP, {0.0}, {1.0}, 2.0, static_cast<std::size_t>(0.1 * kP));
    // The generator's sawtooth starts each cycle at the slip a quarter cycle in; align the added harmonic.
    for (std::size_t k = 0; k < kLength; ++k)
        s.force[k] += std::sin(2.0 * 2.0 * M_PI * (static_cast<double>(k) / kP - 0.25)) / (2.0 * M_PI);
    const auto b = classifyBoth(s);
    print("sawtooth + corner", b);
    for (const auto& r : {b.state, b.force})
    {
        EXPECT_EQ(r.regime, Regime::SMotion);
        EXPECT_NEAR(r.sawtoothness, 2.0, 0.1);
    }
}

TEST(RegimeClassifier, TwoSlipsPerPeriodIsDoubleSlipping)
{
    const auto s =
        test::stickSlip(kLength, kP, {0.0, 0.42}, {0.6, 0.4}, 1.0, static_cast<std::size_t>(0.08 * kP));
    const auto b = classifyBoth(s);
    print("2 slips/P", b);
    for (const auto& r : {b.state, b.force})
    {
        EXPECT_EQ(r.regime, Regime::DoubleSlipping);
        EXPECT_EQ(r.slipsPerCycle, 2);
        EXPECT_NEAR(r.slipsPerPeriod, 2.0, 0.02);
        EXPECT_NEAR(r.measuredPeriod / kP, 1.0, 0.003);
    }
}

// Two equal slips per period: the pattern repeats every P/2, which divides P -> still double slipping.
TEST(RegimeClassifier, EvenlySpacedTwoSlipsPerPeriodIsDoubleSlipping)
{
    const auto s =
        test::stickSlip(kLength, kP, {0.0, 0.5}, {0.5, 0.5}, 1.0, static_cast<std::size_t>(0.08 * kP));
    const auto b = classifyBoth(s);
    print("2 even slips/P", b);
    for (const auto& r : {b.state, b.force})
        EXPECT_EQ(r.regime, Regime::DoubleSlipping);
}

TEST(RegimeClassifier, ThreeSlipsPerPeriodIsMultipleSlipping)
{
    const auto s = test::stickSlip(kLength, kP, {0.0, 0.3, 0.62}, {0.5, 0.3, 0.2}, 1.0,
                                   static_cast<std::size_t>(0.06 * kP));
    const auto b = classifyBoth(s);
    print("3 slips/P", b);
    for (const auto& r : {b.state, b.force})
    {
        EXPECT_EQ(r.regime, Regime::MultipleSlipping);
        EXPECT_EQ(r.slipsPerCycle, 3);
        EXPECT_NEAR(r.slipsPerPeriod, 3.0, 0.03);
    }
}

TEST(RegimeClassifier, OctaveLowPeriodIsAnomalousLowFrequency)
{
    const auto s = test::stickSlip(kLength, 2.0 * kP, {0.0}, {1.0}, 1.0, static_cast<std::size_t>(0.1 * kP));
    const auto b = classifyBoth(s);
    print("period 2P", b);
    for (const auto& r : {b.state, b.force})
    {
        EXPECT_EQ(r.regime, Regime::AnomalousLowFrequency);
        EXPECT_NEAR(r.measuredPeriod / kP, 2.0, 0.005);
        EXPECT_NEAR(r.pitchCents, -1200.0, 3.0);
    }
}

// Force alone: white noise has no period. State: slips at random intervals (0.3..1.7 P) have none either.
TEST(RegimeClassifier, NoiseAndRandomSlipsAreRaucous)
{
    std::vector<double> noise(kLength, 0.0);
    test::addNoise(noise, 1.0, 3);
    const auto force = classifyFromBridgeForce(noise, kP, kWindow);
    EXPECT_EQ(force.regime, Regime::Raucous);

    std::vector<bool> sticking(kLength, true);
    std::vector<double> bridge(kLength, 0.0);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.3, 1.7);
    double level = 0.0;
    for (double at = 0.25 * kP; at < static_cast<double>(kLength); at += u(rng) * kP)
        for (auto k = static_cast<std::size_t>(at);
             k < std::min(kLength, static_cast<std::size_t>(at + 0.1 * kP)); ++k)
            sticking[k] = false;
    for (std::size_t k = 0; k < kLength; ++k)
        bridge[k] = level =
            sticking[k] ? level + 1.0 / kP : level - 0.1; // rise while stuck, fall while slipping
    const auto state = classifyFromState(sticking, bridge, kP, kWindow);
    EXPECT_EQ(state.regime, Regime::Raucous);
    std::printf(
        "[figure] white noise (force): %s, interval cv %.3f, pattern error %.3f; random slips (state): "
        "%s, interval cv %.3f, slips/P %.3f\n",
        regimeName(force.regime), force.intervalCv, force.patternError, regimeName(state.regime),
        state.intervalCv, state.slipsPerPeriod);
}

// State: the string never sticks -> constant slipping; never slips -> no-slip. Force alone: a steady level
// with known sensor noise -> constant slipping; a force rising with the bow and never falling -> no-slip.
TEST(RegimeClassifier, NoStickingIsConstantSlippingAndNoSlipIsNoSlip)
{
    const std::vector<double> flat(kLength, 0.4);
    const auto sliding = classifyFromState(std::vector<bool>(kLength, false), flat, kP, kWindow);
    const auto stuck = classifyFromState(std::vector<bool>(kLength, true), flat, kP, kWindow);
    EXPECT_EQ(sliding.regime, Regime::ConstantSlipping);
    EXPECT_EQ(stuck.regime, Regime::NoSlip);
    EXPECT_DOUBLE_EQ(sliding.slipFraction, 1.0);
    EXPECT_DOUBLE_EQ(stuck.slipFraction, 0.0);

    ForceOnsetOptions sensor;
    sensor.noiseRms = 0.003 * 0.4;
    auto steady = flat;
    test::addNoise(steady, sensor.noiseRms);
    const auto steadyForce = classifyFromBridgeForce(test::highPass(steady, 0.5, kFs), kP, kWindow, sensor);
    std::vector<double> ramp(kLength);
    for (std::size_t k = 0; k < kLength; ++k)
        ramp[k] = 2.0 * static_cast<double>(k) / kFs; // N, dragged at 2 N/s
    test::addNoise(ramp, sensor.noiseRms);
    const auto rampForce = classifyFromBridgeForce(test::highPass(ramp, 0.5, kFs), kP, kWindow, sensor);
    EXPECT_EQ(steadyForce.regime, Regime::ConstantSlipping);
    EXPECT_EQ(rampForce.regime, Regime::NoSlip);
    std::printf("[figure] no sticking (state) -> %s, no slip (state) -> %s, steady force -> %s, rising force "
                "-> %s\n",
                regimeName(sliding.regime), regimeName(stuck.regime), regimeName(steadyForce.regime),
                regimeName(rampForce.regime));
}

} // namespace ROSIN_FILE_LOCAL
