// A record that starts late (an acquisition's trigger latency, different in every trial) must not change the
// times the features read, where the bow velocity is recorded: a trial simulated with the default model,
// recorded once on time and once 0.8 ms late, gives the same first-slip time and creep index (the second
// method is the on-time record), and without the velocity channel the late one is 0.8 ms off.
#include <gtest/gtest.h>

#include "discovery/TrialSimulator.h"
#include "discovery/discover/TrialFeatures.h"

using namespace rosin::discovery;

namespace
{
constexpr double kFs = 44100.0;

std::vector<double> late(std::vector<double> x, std::size_t samples)
{
    const std::size_t n = x.size();
    x.insert(x.begin(), samples, 0.0);
    x.resize(n);
    return x;
}
} // namespace

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
