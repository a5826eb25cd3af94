// The measurement chain of synthetic datasets: the force gauges' high-pass is the one the lab's first-slip
// analysis undoes (exactly), velocities pass unfiltered, and the noise floor has the stated rms.
#include <gtest/gtest.h>

#include <cmath>

#include "core/analysis/FirstSlip.h"
#include "lab/discovery/SensorChain.h"

using namespace rosin::discovery;

TEST(SensorChain, HighPassIsUndoneExactlyByTheLab)
{
    const double fs = 44100.0;
    std::vector<double> x(20000);
    for (std::size_t n = 0; n < x.size(); ++n)
        x[n] = 0.5 * std::pow(n / fs, 2) * 40.0 + 0.1 * std::sin(0.02 * n); // a pre-slip parabola and a tone
    std::vector<double> y = x;
    firstOrderHighPass(y, 0.5, fs);
    EXPECT_LT(y.back(), 0.9 * x.back()); // the slow rise is visibly lost ...
    const auto back = rosin::analysis::undoFirstOrderHighPass(y, 0.5, fs);
    for (std::size_t n = 0; n < x.size(); ++n)
        ASSERT_NEAR(back[n], x[n], 1e-9) << n; // ... and recovered
}

TEST(SensorChain, OnlyForceChannelsAreHighPassed)
{
    const std::vector<Channel> layout{{"bridgeForce", "N"}, {"bowVelocity", "m/s"}};
    std::vector<std::vector<double>> channels{std::vector<double>(1000, 1.0), std::vector<double>(1000, 1.0)};
    Sensor sensor;
    sensor.highpassHz = 0.5;
    applySensorResponse(layout, channels, sensor, 1000.0);
    EXPECT_LT(channels[0].back(), 0.999);
    EXPECT_EQ(channels[1].back(), 1.0);
    EXPECT_TRUE(passesSensorHighPass({"frictionForce", "N"}));
    EXPECT_FALSE(passesSensorHighPass({"bowPointVelocity", "m/s"}));

    Sensor none; // no high-pass stated: nothing filtered
    std::vector<std::vector<double>> flat{std::vector<double>(10, 1.0)};
    applySensorResponse({{"bridgeForce", "N"}}, flat, none, 1000.0);
    EXPECT_EQ(flat[0].back(), 1.0);
}

TEST(SensorChain, NoiseHasTheStatedRms)
{
    std::vector<std::vector<double>> channels{std::vector<double>(100000, 0.0)};
    Sensor sensor;
    sensor.noiseRms = 0.002;
    SeededRandom random(3, RandomStream::Noise, 0);
    addSensorNoise(channels, sensor, random);
    double sumSq = 0.0;
    for (double v : channels[0])
        sumSq += v * v;
    EXPECT_NEAR(std::sqrt(sumSq / 100000.0), 0.002, 0.00002);
}
