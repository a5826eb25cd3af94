// A record that starts late (an acquisition's trigger latency, different in every trial) must not change the
// times the features read, where the bow velocity is recorded: a trial simulated with the default model,
// recorded once on time and once 0.8 ms late, gives the same first-slip time and creep index (the second
// method is the on-time record), and without the velocity channel the late one is 0.8 ms off.
#include <gtest/gtest.h>

#include "core/analysis/Regime.h"
#include "lab/discovery/TrialSimulator.h"
#include "lab/discovery/discover/TrialFeatures.h"

#include <cmath>

using namespace rosin::discovery;

namespace ROSIN_FILE_LOCAL
{
constexpr double kFs = 44100.0;

std::vector<double> late(std::vector<double> x, std::size_t samples)
{
    const std::size_t n = x.size();
    x.insert(x.begin(), samples, 0.0);
    x.resize(n);
    return x;
}

TEST(TrialFeatures, ALateRecordIsAlignedToTheStrokeByItsBowVelocity)
{
    TrialSimulator sim(SimulationModel{}, kFs);
    TrialSettings t;
    t.bowForce = 1.5;
    t.gesture = ConstantAcceleration{2.5};
    t.seconds = 0.25;
    const auto& samples = sim.run(t);
    const auto force = channelSamples(samples, "bridgeForce");
    const auto velocity = channelSamples(samples, "bowVelocity");
    FeatureContext c;
    c.sampleRate = kFs;
    c.bowForce = t.bowForce;
    c.gesture = t.gesture;
    c.periodSeconds = sim.periodSeconds();

    const std::size_t delay = 35; // 0.79 ms
    const auto onTime = computeTrialFeatures(force, c, {nullptr, nullptr, &velocity});
    const auto lateForce = late(force, delay);
    const auto lateVelocity = late(velocity, delay);
    const auto aligned = computeTrialFeatures(lateForce, c, {nullptr, nullptr, &lateVelocity});
    const auto unaligned = computeTrialFeatures(lateForce, c);
    ASSERT_TRUE(onTime[kFirstSlipTime] && onTime[kCreep]);
    ASSERT_TRUE(aligned[kFirstSlipTime] && aligned[kCreep] && unaligned[kFirstSlipTime]);

    EXPECT_NEAR(*aligned[kFirstSlipTime], *onTime[kFirstSlipTime], 2e-5);
    EXPECT_NEAR(*aligned[kCreep], *onTime[kCreep], 1e-3); // 1/5 of the creep index's resolution
    EXPECT_NEAR(*unaligned[kFirstSlipTime] - *onTime[kFirstSlipTime], delay / kFs, 2e-5);
}

// The features of a steady note simulated with the default model at (beta, force) and 0.1 m/s.
TrialFeatures steadyNote(double beta, double bowForce, double seconds)
{
    TrialSimulator sim(SimulationModel{}, kFs);
    TrialSettings t;
    t.beta = beta;
    t.bowForce = bowForce;
    t.gesture = Steady{0.1};
    t.seconds = seconds;
    const auto force = channelSamples(sim.run(t), "bridgeForce");
    FeatureContext c;
    c.sampleRate = kFs;
    c.beta = t.beta;
    c.bowForce = t.bowForce;
    c.gesture = t.gesture;
    c.periodSeconds = sim.periodSeconds();
    c.impedance =
        std::sqrt(SimulationModel{}.preset.string.tension * SimulationModel{}.preset.string.massPerLength);
    return computeTrialFeatures(force, c);
}

// Ideal Helmholtz motion drives the bridge with a sawtooth of peak-to-peak 2 Z0 v_b / beta (the corner's
// slope jump times T); a simulated steady note in Helmholtz motion keeps most of it: its steadyLevel
// lies within a dB or two below 0 dB (the losses round the corner, the body takes a little), and its
// pitch is a few cents flat, not a whole sample (5.8 cents) of quantisation.
TEST(TrialFeatures, SteadyHelmholtzMotionHasTheIdealSawtoothLevel)
{
    const auto f = steadyNote(0.1, 0.5, 1.0);
    ASSERT_TRUE(f[kRegime].has_value());
    ASSERT_EQ(*f[kRegime], static_cast<double>(rosin::analysis::Regime::Helmholtz));
    ASSERT_TRUE(f[kSteadyLevel] && f[kPitchCents]);
    EXPECT_LT(*f[kSteadyLevel], 0.5);
    EXPECT_GT(*f[kSteadyLevel], -2.0);
    EXPECT_LT(*f[kPitchCents], 1.0); // flat or at pitch, never sharp by more than a cent
    EXPECT_GT(*f[kPitchCents], -15.0);
}

// Above Schelleng's maximum force the motion is raucous: no pitch, no tilt, but the level is read (most
// of a Schelleng scan lies outside Helmholtz motion) and lies within the sawtooth's range.
TEST(TrialFeatures, SteadyLevelIsReadOutsideHelmholtzMotionToo)
{
    const auto f = steadyNote(0.1, 4.0, 0.5);
    ASSERT_TRUE(f[kRegime].has_value());
    ASSERT_NE(*f[kRegime], static_cast<double>(rosin::analysis::Regime::Helmholtz));
    EXPECT_FALSE(f[kPitchCents] || f[kHarmonicTilt]);
    ASSERT_TRUE(f[kSteadyLevel].has_value());
    EXPECT_LT(*f[kSteadyLevel], 6.0);
    EXPECT_GT(*f[kSteadyLevel], -20.0);
}

} // namespace ROSIN_FILE_LOCAL
