// writeDatasetDescription writes what readDatasetDescription reads back field for field, and refuses to write
// what the reader would reject.
#include <gtest/gtest.h>

#include "lab/discovery/DatasetFixtures.h"
#include "lab/discovery/DatasetReader.h"
#include "lab/discovery/DatasetWriter.h"

namespace rosin::discovery
{
namespace ROSIN_FILE_LOCAL
{

void expectSameString(const physics::StringParameters& a, const physics::StringParameters& b)
{
    EXPECT_EQ(a.tension, b.tension);
    EXPECT_EQ(a.massPerLength, b.massPerLength);
    EXPECT_EQ(a.length, b.length);
    EXPECT_EQ(a.bendingStiffness, b.bendingStiffness);
    EXPECT_EQ(a.lossF, b.lossF);
    EXPECT_EQ(a.stoppedLossF, b.stoppedLossF);
    EXPECT_EQ(a.lossB, b.lossB);
    EXPECT_EQ(a.lossA, b.lossA);
    EXPECT_EQ(a.torsionalWaveSpeed, b.torsionalWaveSpeed);
    EXPECT_EQ(a.torsionalQ, b.torsionalQ);
    EXPECT_EQ(a.torsionalImpedance, b.torsionalImpedance);
}

void expectSameDataset(const Dataset& a, const Dataset& b)
{
    EXPECT_EQ(a.description, b.description);
    EXPECT_EQ(a.sampleRate, b.sampleRate);
    EXPECT_EQ(a.channels, b.channels);
    expectSameString(a.rig.string, b.rig.string);
    EXPECT_EQ(a.rig.defaultedStringFields, b.rig.defaultedStringFields);
    EXPECT_EQ(a.rig.body, b.rig.body);
    EXPECT_EQ(a.rig.bow, b.rig.bow);
    EXPECT_EQ(a.rig.ambientTemperature, b.rig.ambientTemperature);
    EXPECT_EQ(a.sensor.highpassHz, b.sensor.highpassHz);
    EXPECT_EQ(a.sensor.noiseRms, b.sensor.noiseRms);
    EXPECT_EQ(a.trials, b.trials); // every trial field, gesture included
}

TEST(DatasetRoundTrip, SpecExampleSurvivesWriteAndRead)
{
    test::DatasetFolder source, copy;
    source.describe(std::string(test::kSpecExample));
    const Dataset original = readDatasetDescription(source.path());
    writeDatasetDescription(original, copy.path());
    const Dataset back = readDatasetDescription(copy.path());
    expectSameDataset(original, back);
    EXPECT_EQ(back.folder, copy.path());
}

TEST(DatasetRoundTrip, EveryFieldAndEveryGestureSurvive)
{
    Dataset d;
    d.description = "synthetic: \"quotes\", unicode \u00b5, newline\n";
    d.sampleRate = 96000;
    d.channels = {{"frictionForce", "N"},
                  {"bowPointVelocity", "m/s"},
                  {"bowVelocity", "m/s"},
                  {"bowForceMeasured", "N"}};
    d.rig.string = physics::stringFromCatalogue("cello-D3");
    d.rig.string.tension = 0.1 + 0.2; // not exactly representable in short decimal: must survive bit-exact
    d.rig.string.massPerLength = 1.0 / 3.0;
    d.rig.string.length = 0.6906;
    d.rig.string.lossA = 0.0;
    d.rig.string.stoppedLossF = d.rig.string.lossF;
    d.rig.defaultedStringFields = {"bendingStiffness", "torsionalQ"};
    d.rig.body = "bodies/my-cello.json";
    d.rig.bow = "a pernambuco bow, 60 g";
    d.rig.ambientTemperature = -5.25;
    d.sensor.highpassHz = 0.0;
    Trial a{"a", "trials/a.wav", 0.0899, 0.84, ConstantAcceleration{1.56}, true, std::nullopt, std::nullopt};
    Trial s{"s_2", "s_2.wav", 1e-3, 2.5, Steady{-0.1}, false, 31.0, 7};
    Trial r{"R-3", "trials/deep/R-3.wav", 0.4999, 1e-6, Recorded{}, true, std::nullopt, -1};
    d.trials = {a, s, r};

    test::DatasetFolder folder;
    writeDatasetDescription(d, folder.path());
    const Dataset back = readDatasetDescription(folder.path());
    expectSameDataset(d, back);
    // The defaulted fields stay absent from the file, so they stay "defaulted" on reading.
    const auto json = nlohmann::json::parse(std::ifstream(folder.descriptionPath()));
    EXPECT_FALSE(json["rig"]["string"].contains("bendingStiffness"));
    EXPECT_TRUE(json["rig"]["string"].contains("lossA"));
    EXPECT_FALSE(json["sensor"].contains("noiseRms"));
}

TEST(DatasetRoundTrip, RefusesToWriteWhatTheReaderRejects)
{
    test::DatasetFolder source, target;
    source.describe(std::string(test::kSpecExample));
    Dataset d = readDatasetDescription(source.path());
    d.trials[0].beta = 0.7;
    try
    {
        writeDatasetDescription(d, target.path());
        FAIL() << "wrote an invalid dataset";
    }
    catch (const DatasetError& e)
    {
        EXPECT_EQ(e.field(), "trials[0].beta");
        EXPECT_EQ(e.file(), target.descriptionPath());
    }
    EXPECT_FALSE(std::filesystem::exists(target.descriptionPath()));
}

TEST(DatasetRoundTrip, CreatesTheFolder)
{
    test::DatasetFolder source, parent;
    source.describe(std::string(test::kSpecExample));
    const std::string folder = parent.path() + "/new/scan";
    writeDatasetDescription(readDatasetDescription(source.path()), folder);
    EXPECT_EQ(readDatasetDescription(folder).trials.size(), 1u);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::discovery
