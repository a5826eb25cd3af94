// readDatasetDescription on files that follow the spec: the spec's own example, what it leaves optional, and
// the cello-D3 defaults it reports.
#include <gtest/gtest.h>

#include "core/physics/string/StringParameters.h"
#include "lab/discovery/DatasetFixtures.h"
#include "lab/discovery/DatasetReader.h"

namespace rosin::discovery
{
namespace ROSIN_FILE_LOCAL
{

TEST(DatasetReader, AcceptsTheSpecExample)
{
    test::DatasetFolder folder;
    folder.describe(std::string(test::kSpecExample));
    const Dataset d = readDatasetDescription(folder.path());

    EXPECT_EQ(d.folder, folder.path());
    EXPECT_EQ(d.description, "Guettler scan, cello D string, rosin-coated acrylic rod");
    EXPECT_EQ(d.sampleRate, 44100);
    ASSERT_EQ(d.channels.size(), 2u);
    EXPECT_EQ(d.channels[0], (Channel{"bridgeForce", "N"}));
    EXPECT_EQ(d.channels[1], (Channel{"bowVelocity", "m/s"}));

    const auto& s = d.rig.string;
    EXPECT_EQ(s.tension, 111.0);
    EXPECT_EQ(s.massPerLength, 0.0027);
    EXPECT_EQ(s.length, 0.69);
    EXPECT_EQ(s.bendingStiffness, 3.0e-4);
    EXPECT_EQ(s.lossF, 23.0);
    EXPECT_EQ(s.stoppedLossF, 23.0); // the measured string is bowed open at its vibrating length
    EXPECT_EQ(s.lossB, 12.5);
    EXPECT_EQ(s.lossA, 0.11);
    EXPECT_EQ(s.torsionalWaveSpeed, 758.0);
    EXPECT_EQ(s.torsionalQ, 45.0);
    EXPECT_EQ(s.torsionalImpedance, 1.8);
    EXPECT_TRUE(d.rig.defaultedStringFields.empty());
    EXPECT_EQ(describeStringDefaults(d.rig), "");
    EXPECT_EQ(d.rig.body, "cello");
    EXPECT_EQ(d.rig.bow.at("material"), "acrylic");
    EXPECT_EQ(d.rig.ambientTemperature, 20.0);
    EXPECT_EQ(d.sensor.highpassHz, 0.5);
    EXPECT_EQ(d.sensor.noiseRms, 0.002);

    ASSERT_EQ(d.trials.size(), 1u);
    const Trial& t = d.trials[0];
    EXPECT_EQ(t.id, "b0899-f03-a10");
    EXPECT_EQ(t.file, "trials/b0899-f03-a10.wav");
    EXPECT_EQ(t.beta, 0.0899);
    EXPECT_EQ(t.bowForce, 0.84);
    ASSERT_TRUE(std::holds_alternative<ConstantAcceleration>(t.gesture));
    EXPECT_EQ(std::get<ConstantAcceleration>(t.gesture).acceleration, 1.56);
    EXPECT_TRUE(t.valid);
    EXPECT_FALSE(t.ambientTemperature);
    EXPECT_FALSE(t.repeat);
    EXPECT_EQ(d.ambientTemperature(t), 20.0);
    EXPECT_EQ(d.descriptionPath(), folder.descriptionPath());
}

TEST(DatasetReader, OnlyTheRequiredFieldsUseCelloD3DefaultsAndSaySo)
{
    auto j = test::specExample();
    j.erase("description");
    j.erase("sensor");
    j["rig"] = {{"string", {{"tension", 72.5}, {"massPerLength", 4.2e-4}, {"length", 0.33}}}};
    j["trials"][0].erase("valid");
    test::DatasetFolder folder;
    folder.describe(j);
    const Dataset d = readDatasetDescription(folder.path());

    const auto d3 = physics::stringFromCatalogue("cello-D3");
    EXPECT_EQ(d.rig.string.tension, 72.5);
    EXPECT_EQ(d.rig.string.length, 0.33);
    EXPECT_EQ(d.rig.string.bendingStiffness, d3.bendingStiffness);
    EXPECT_EQ(d.rig.string.lossF, d3.lossF);
    EXPECT_EQ(d.rig.string.torsionalImpedance, d3.torsionalImpedance);
    EXPECT_EQ(d.rig.defaultedStringFields,
              (std::vector<std::string>{"bendingStiffness", "lossF", "lossB", "lossA", "torsionalWaveSpeed",
                                        "torsionalQ", "torsionalImpedance"}));
    EXPECT_EQ(describeStringDefaults(d.rig),
              "rig.string: bendingStiffness = 3e-04, lossF = 23, lossB = 12.5, lossA = 0.11, "
              "torsionalWaveSpeed = 758, torsionalQ = 45, torsionalImpedance = 1.8 taken from the catalogue "
              "string cello-D3");
    EXPECT_FALSE(d.rig.body);
    EXPECT_TRUE(d.rig.bow.is_null());
    EXPECT_FALSE(d.rig.ambientTemperature);
    EXPECT_FALSE(d.sensor.highpassHz);
    EXPECT_FALSE(d.sensor.noiseRms);
    EXPECT_EQ(d.description, "");
    EXPECT_TRUE(d.trials[0].valid); // absent means valid
    EXPECT_FALSE(d.ambientTemperature(d.trials[0]));
}

TEST(DatasetReader, AcceptsEveryGestureTypeOptionalTrialFieldsAndUnknownExtras)
{
    auto j = test::specExample();
    j["labNotebook"] = "p. 42"; // "optional fields may be added"
    j["channels"][0]["calibration"] = 1.02;
    j["rig"]["string"]["coreMaterial"] = "steel";
    j["sampleRate"] = 48000.0; // an integral number written as a float is still an integer
    auto steady = j["trials"][0];
    steady["id"] = "s_1";
    steady["file"] = "trials/sub/../s_1.wav"; // stays inside the folder
    steady["gesture"] = {{"type", "steady"}, {"speed", -0.05}, {"operator", "KG"}};
    steady["ambientTemperature"] = 23.5;
    steady["repeat"] = 2;
    steady["valid"] = false;
    auto recorded = j["trials"][0];
    recorded["id"] = "REC";
    recorded["file"] = "rec.wav";
    recorded["gesture"] = {{"type", "recorded"}};
    j["trials"].push_back(steady);
    j["trials"].push_back(recorded);
    test::DatasetFolder folder;
    folder.describe(j);
    const Dataset d = readDatasetDescription(folder.path());

    EXPECT_EQ(d.sampleRate, 48000);
    ASSERT_EQ(d.trials.size(), 3u);
    EXPECT_EQ(std::get<Steady>(d.trials[1].gesture).speed, -0.05);
    EXPECT_EQ(d.trials[1].ambientTemperature, 23.5);
    EXPECT_EQ(d.ambientTemperature(d.trials[1]), 23.5);
    EXPECT_EQ(d.trials[1].repeat, 2);
    EXPECT_FALSE(d.trials[1].valid);
    EXPECT_TRUE(std::holds_alternative<Recorded>(d.trials[2].gesture));
    EXPECT_EQ(gestureTypeName(d.trials[2].gesture), "recorded");
    EXPECT_EQ(d.trialIndex("REC"), 2u);
    EXPECT_EQ(d.channelIndex("bowVelocity"), 1u);
    EXPECT_FALSE(d.channelIndex("frictionForce"));
}

TEST(DatasetReader, AcceptsTheSampleRateLimitsAndEveryChannelKind)
{
    auto j = test::specExample();
    j["channels"] = nlohmann::json::array();
    for (const auto& [name, unit] : {std::pair{"bowForceMeasured", "N"}, std::pair{"frictionForce", "N"},
                                     std::pair{"bowPointVelocity", "m/s"}, std::pair{"bowVelocity", "m/s"},
                                     std::pair{"bridgeForce", "N"}})
        j["channels"].push_back({{"name", name}, {"unit", unit}});
    for (int rate : {1000, 384000})
    {
        j["sampleRate"] = rate;
        test::DatasetFolder folder;
        folder.describe(j);
        const Dataset d = readDatasetDescription(folder.path());
        EXPECT_EQ(d.sampleRate, rate);
        EXPECT_EQ(d.channels.size(), 5u);
        EXPECT_EQ(d.channels[0].name, "bowForceMeasured");
    }
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::discovery
