// rosin discover's simulated trials: a fit that changes only the measurement chain (gain, low-pass, lag)
// reuses the string's simulation, and the features are then exactly those of a fresh simulation.
#include <gtest/gtest.h>

#include <vector>

#include "core/physics/string/StringParameters.h"
#include "lab/discovery/discover/ModelRuns.h"

namespace ROSIN_FILE_LOCAL
{
using namespace rosin::discovery;

// Two short trials of the cello D string on the cello body, bridge force and bow velocity recorded.
Dataset twoTrials()
{
    Dataset d;
    d.folder = "in-memory";
    d.sampleRate = 44100;
    d.channels = {{"bridgeForce", "N"}, {"bowVelocity", "m/s"}};
    d.rig.string = rosin::physics::stringFromCatalogue("cello-D3");
    d.rig.body = "cello";
    d.sensor.highpassHz = 0.5;
    d.trials = {Trial{.id = "a",
                      .file = "a.wav",
                      .beta = 0.0899,
                      .bowForce = 0.8,
                      .gesture = ConstantAcceleration{1.5}},
                Trial{.id = "b",
                      .file = "b.wav",
                      .beta = 0.0899,
                      .bowForce = 0.4,
                      .gesture = ConstantAcceleration{3.0}}};
    return d;
}

TEST(ModelRuns, ChainOnlyChangeReusesTheStringAndGivesTheSameFeatures)
{
    const Dataset d = twoTrials();
    const std::vector<std::size_t> both{0, 1};
    const std::vector<double> seconds{0.25, 0.25};
    const SimulationModel nominal = baselineModel(d, "plastic");
    SimulationModel chained = nominal;
    chained.nuisance.sensorGain = 1.02;
    chained.nuisance.sensorBandwidth = 0.3;
    chained.nuisance.sensorDelay = 0.0005;

    StringRuns runs;
    const auto first = simulateFeatures(nominal, d, both, seconds, 1, {}, &runs);
    ASSERT_EQ(runs.size(), d.trials.size());
    for (const auto& run : runs)
        ASSERT_EQ(run.channels.size(), 2u);
    const auto fresh = simulateFeatures(chained, d, both, seconds, 1);
    const auto reused = simulateFeatures(chained, d, both, seconds, 1, {}, &runs);
    for (std::size_t i : both)
        EXPECT_EQ(reused[i], fresh[i]) << "trial " << i;
    // The chain matters (so the equality above says something), and the kept runs are what is read.
    EXPECT_NE(first, fresh);
    StringRuns silenced = runs;
    for (double& x : silenced[0].channels[0])
        x = 0.0;
    const auto fromSilence = simulateFeatures(chained, d, both, seconds, 1, {}, &silenced);
    EXPECT_NE(fromSilence[0], fresh[0]);
    EXPECT_EQ(fromSilence[1], fresh[1]);
}

} // namespace ROSIN_FILE_LOCAL
