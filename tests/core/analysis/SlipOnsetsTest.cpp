// Slip onsets from the solver's state and from the bridge force alone ([Notes §7.2]).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/analysis/Signals.h"
#include "core/analysis/SlipOnsets.h"

using namespace rosin::analysis;

namespace ROSIN_FILE_LOCAL
{
constexpr double kFs = 48000.0;
constexpr double kP = kFs / 146.8; // cello D3, samples

TEST(SlipOnsets, EpisodesFromStateAreTheRunsOfSliding)
{
    // Samples 0..9, 1 = sticking.
    std::vector<bool> s;
    for (const char c : std::string("0011010001"))
        s.push_back(c == '1');
    const auto e = slipEpisodesFromState(s);
    // The run at sample 0 began before the record: no onset. Then 4 (1 sample) and 6 (3 samples).
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[0].onset, 4u);
    EXPECT_EQ(e[0].duration, 1u);
    EXPECT_EQ(e[1].onset, 6u);
    EXPECT_EQ(e[1].duration, 3u);
    EXPECT_DOUBLE_EQ(slipFraction(s, 0, s.size()), 0.6);
}

TEST(SlipOnsets, EpisodesFromRelativeVelocityIgnoreChatterAndMarkFlybacks)
{
    const double vb = 0.1;
    // Sticking with chatter (|dv| < 1 % of v_b), a partial slip (lags the bow), a flyback (moves backwards).
    const std::vector<double> dv{0.0005, -0.0008, 0.0, -0.05, -0.06, 0.0, 0.0009, -0.3, -0.5, -0.2, 0.0};
    const std::vector<double> bow(dv.size(), vb);
    const auto e = slipEpisodesFromRelativeVelocity(dv, 0.01 * vb, bow);
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[0].onset, 3u);
    EXPECT_EQ(e[0].duration, 2u);
    EXPECT_FALSE(e[0].flyback);
    EXPECT_EQ(e[1].onset, 7u);
    EXPECT_EQ(e[1].duration, 3u);
    EXPECT_TRUE(e[1].flyback);
    ASSERT_EQ(flybacksOnly(e).size(), 1u);
    EXPECT_EQ(flybacksOnly(e)[0].onset, 7u);
}

TEST(SlipOnsets, EpisodesFromVoiceSamplesMarkFlybacks)
{
    const double vb = 0.1;
    std::vector<rosin::physics::VoiceSample> v(10);
    for (auto& s : v)
        s.bowVelocity = s.bowPointVelocity = vb; // sticking: the string moves with the bow
    v[2].sticking = v[3].sticking = false;       // lags the bow: partial slip
    v[2].bowPointVelocity = v[3].bowPointVelocity = 0.05;
    v[6].sticking = v[7].sticking = false; // moves backwards: flyback
    v[6].bowPointVelocity = -0.05;
    v[7].bowPointVelocity = -0.2;
    const auto e = slipEpisodesFromVoice(v);
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[0].onset, 2u);
    EXPECT_FALSE(e[0].flyback);
    EXPECT_EQ(e[1].onset, 6u);
    EXPECT_EQ(e[1].duration, 2u);
    EXPECT_TRUE(e[1].flyback);
}

// Ideal Helmholtz motion at beta 0.1 flies back at v_b / beta = 1 m/s relative to a 0.1 m/s bow: a
// flyback reaching 0.3 m/s (30 %) counts at a 25 % share, a short reversal to -0.02 m/s (dv = 0.12 m/s,
// 12 %) does not; episodes without velocities (from the state alone) pass unjudged.
TEST(SlipOnsets, FullFlybacksReachAShareOfTheHelmholtzFlybackSpeed)
{
    const double vb = 0.1, beta = 0.1;
    std::vector<rosin::physics::VoiceSample> v(12);
    for (auto& s : v)
        s.bowVelocity = s.bowPointVelocity = vb;
    v[2].sticking = v[3].sticking = false; // a short reversal
    v[2].bowPointVelocity = -0.01, v[3].bowPointVelocity = -0.02;
    v[7].sticking = v[8].sticking = false; // a flyback
    v[7].bowPointVelocity = -0.1, v[8].bowPointVelocity = -0.2;
    const auto e = slipEpisodesFromVoice(v);
    ASSERT_EQ(flybacksOnly(e).size(), 2u);
    EXPECT_DOUBLE_EQ(e[0].peakSlipSpeed, 0.12);
    EXPECT_DOUBLE_EQ(e[1].peakSlipSpeed, 0.3);
    EXPECT_DOUBLE_EQ(e[1].bowSpeedAtOnset, vb);
    const auto full = fullFlybacksOnly(e, beta, 0.25);
    ASSERT_EQ(full.size(), 1u);
    EXPECT_EQ(full[0].onset, 7u);
    EXPECT_EQ(fullFlybacksOnly(e, beta, 0.1).size(), 2u);
    EXPECT_EQ(fullFlybacksOnly(e, beta, 0.35).size(), 0u);
    std::vector<bool> sticking(12, true);
    sticking[4] = false;
    EXPECT_EQ(fullFlybacksOnly(slipEpisodesFromState(sticking), beta, 0.25).size(), 1u);
}

// A Helmholtz sawtooth with ~1/beta Schelleng ripples, 0.3 % noise and a 0.5 Hz sensor high-pass: every
// flyback found, at the right sample, and nothing else.
TEST(SlipOnsets, BridgeForceFlybacksFoundThroughNoiseAndRipple)
{
    const auto s = rosin::analysis::test::stickSlip(static_cast<std::size_t>(0.5 * kFs), kP, {0.0}, {1.0},
                                                    1.0, static_cast<std::size_t>(0.1 * kP), 11.0, 0.03);
    const auto y = rosin::analysis::test::measured(s.force, 0.003, 0.5, kFs);
    const auto onsets = slipOnsetsFromBridgeForce(y, kP);
    ASSERT_EQ(onsets.size(), s.onsets.size());
    long worst = 0;
    for (std::size_t i = 0; i < onsets.size(); ++i)
        worst = std::max(worst, std::abs(static_cast<long>(onsets[i]) - static_cast<long>(s.onsets[i])));
    EXPECT_LE(worst, 1);
    std::printf("[figure] force onsets, sawtooth + ripple + 0.3 %% noise + 0.5 Hz HP: %zu of %zu found, "
                "worst timing error %ld samples\n",
                onsets.size(), s.onsets.size(), worst);
}

// A smooth oscillation has no abrupt fall: no slips; with the sensor noise given, neither has a quiet signal.
TEST(SlipOnsets, SmoothOrQuietForceHasNoSlips)
{
    std::vector<double> sine(static_cast<std::size_t>(0.2 * kFs));
    for (std::size_t k = 0; k < sine.size(); ++k)
        sine[k] = std::sin(2.0 * M_PI * static_cast<double>(k) / kP);
    EXPECT_TRUE(slipOnsetsFromBridgeForce(sine, kP).empty());

    std::vector<double> quiet(static_cast<std::size_t>(0.2 * kFs), 0.3);
    rosin::analysis::test::addNoise(quiet, 0.001);
    ForceOnsetOptions o;
    o.noiseRms = 0.001;
    EXPECT_TRUE(slipOnsetsFromBridgeForce(quiet, kP, o).empty());
    std::printf("[figure] force onsets: sine %zu, quiet+noise (noise known) %zu, quiet+noise (unknown) %zu\n",
                slipOnsetsFromBridgeForce(sine, kP).size(), slipOnsetsFromBridgeForce(quiet, kP, o).size(),
                slipOnsetsFromBridgeForce(quiet, kP).size());
}

} // namespace ROSIN_FILE_LOCAL
