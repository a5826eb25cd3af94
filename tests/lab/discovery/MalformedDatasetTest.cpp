// Every malformed dataset.json is rejected with a DatasetError naming the file, the field and what was
// expected; none crashes the reader.
#include <gtest/gtest.h>

#include <functional>

#include "lab/discovery/DatasetFixtures.h"
#include "lab/discovery/DatasetReader.h"

namespace rosin::discovery
{
namespace ROSIN_FILE_LOCAL
{

using Json = nlohmann::json;

struct Case
{
    const char* name;
    std::function<void(Json&)> mutate;
    const char* field;    ///< the JSON path the error must name
    const char* expected; ///< a fragment of what was expected
};

// Reads the mutated spec example and returns the error (fails the test if none).
DatasetError rejection(const Case& c)
{
    auto j = test::specExample();
    c.mutate(j);
    test::DatasetFolder folder;
    folder.describe(j);
    try
    {
        readDatasetDescription(folder.path());
    }
    catch (const DatasetError& e)
    {
        EXPECT_EQ(e.file(), folder.descriptionPath()) << e.what();
        const std::string what = e.what();
        EXPECT_NE(what.find(folder.descriptionPath()), std::string::npos) << what;
        return e;
    }
    ADD_FAILURE() << c.name << ": accepted";
    return DatasetError("", "", "");
}

Json trial(const Json& base, const std::string& id)
{
    Json t = base;
    t["id"] = id;
    t["file"] = "trials/" + id + ".wav";
    return t;
}

const std::vector<Case>& cases()
{
    static const std::vector<Case> all{
        {"missing format", [](Json& j) { j.erase("format"); }, "format", "\"rosin-measurements/1\""},
        {"wrong format", [](Json& j) { j["format"] = "rosin-measurements/2"; }, "format",
         "\"rosin-measurements/1\""},
        {"sample rate 500", [](Json& j) { j["sampleRate"] = 500; }, "sampleRate",
         "an integer in 1000..384000"},
        {"sample rate not integral", [](Json& j) { j["sampleRate"] = 44100.5; }, "sampleRate", "an integer"},
        {"sample rate missing", [](Json& j) { j.erase("sampleRate"); }, "sampleRate", "an integer"},
        {"unknown channel", [](Json& j) { j["channels"][1]["name"] = "bowSpeed"; }, "channels[1].name",
         "one of bridgeForce, frictionForce"},
        {"bridgeForce in mN", [](Json& j) { j["channels"][0]["unit"] = "mN"; }, "channels[0].unit",
         "\"N\" (the unit of bridgeForce)"},
        {"duplicate channel", [](Json& j) { j["channels"][1] = j["channels"][0]; }, "channels[1].name",
         "a channel not listed before"},
        {"no channels", [](Json& j) { j["channels"] = Json::array(); }, "channels", "a non-empty array"},
        {"no force or velocity channel",
         [](Json& j) {
             j["channels"] = Json::array({{{"name", "bowVelocity"}, {"unit", "m/s"}}});
         },
         "channels", "at least one of bridgeForce, frictionForce, bowPointVelocity"},
        {"missing rig", [](Json& j) { j.erase("rig"); }, "rig", "an object"},
        {"missing tension", [](Json& j) { j["rig"]["string"].erase("tension"); }, "rig.string.tension",
         "a number > 0 (N)"},
        {"negative massPerLength", [](Json& j) { j["rig"]["string"]["massPerLength"] = -0.0027; },
         "rig.string.massPerLength", "a number > 0 (kg/m)"},
        {"length as text", [](Json& j) { j["rig"]["string"]["length"] = "0.69"; }, "rig.string.length",
         "a number > 0 (m)"},
        {"negative loss", [](Json& j) { j["rig"]["string"]["lossB"] = -1; }, "rig.string.lossB",
         "a number >= 0"},
        {"empty body", [](Json& j) { j["rig"]["body"] = ""; }, "rig.body", "\"cello\", \"rigid\""},
        {"below absolute zero", [](Json& j) { j["rig"]["ambientTemperature"] = -300; },
         "rig.ambientTemperature", "a number > -273.15 (deg C)"},
        {"negative noise", [](Json& j) { j["sensor"]["noiseRms"] = -0.1; }, "sensor.noiseRms",
         "a number >= 0"},
        {"no trials", [](Json& j) { j["trials"] = Json::array(); }, "trials", "a non-empty array"},
        {"trial not an object", [](Json& j) { j["trials"].push_back(3); }, "trials[1]", "a JSON object"},
        {"duplicate trial id", [](Json& j) { j["trials"].push_back(j["trials"][0]); }, "trials[1].id",
         "an id no other trial has"},
        {"bad id characters", [](Json& j) { j["trials"][0]["id"] = "b 0899/f03"; }, "trials[0].id",
         "letters, digits, '-' and '_'"},
        {"empty id", [](Json& j) { j["trials"][0]["id"] = ""; }, "trials[0].id", "a non-empty id"},
        {"file outside the folder", [](Json& j) { j["trials"][0]["file"] = "../x.wav"; }, "trials[0].file",
         "inside it"},
        {"file climbing out deeper", [](Json& j) { j["trials"][0]["file"] = "trials/../../x.wav"; },
         "trials[0].file", "inside it"},
        {"absolute file", [](Json& j) { j["trials"][0]["file"] = "/etc/passwd"; }, "trials[0].file",
         "inside it"},
        {"file is the folder", [](Json& j) { j["trials"][0]["file"] = "trials/.."; }, "trials[0].file",
         "inside it"},
        {"beta 0.5", [](Json& j) { j["trials"][0]["beta"] = 0.5; }, "trials[0].beta",
         "a number > 0 and < 0.5"},
        {"beta 0", [](Json& j) { j["trials"][0]["beta"] = 0; }, "trials[0].beta", "a number > 0 and < 0.5"},
        {"bowForce 0", [](Json& j) { j["trials"][0]["bowForce"] = 0; }, "trials[0].bowForce",
         "a number > 0 (N)"},
        {"missing gesture", [](Json& j) { j["trials"][0].erase("gesture"); }, "trials[0].gesture",
         "an object"},
        {"unknown gesture type",
         [](Json& j)
         {
             j["trials"].push_back(trial(j["trials"][0], "t2"));
             j["trials"][1]["gesture"]["type"] = "linear-ramp";
         },
         "trials[1].gesture.type", "one of constant-acceleration, steady, recorded"},
        {"gesture type missing", [](Json& j) { j["trials"][0]["gesture"].erase("type"); },
         "trials[0].gesture.type", "one of constant-acceleration"},
        {"acceleration missing",
         [](Json& j)
         {
             for (const char* id : {"t1", "t2", "t3"})
                 j["trials"].push_back(trial(j["trials"][0], id));
             j["trials"][3]["gesture"].erase("acceleration");
         },
         "trials[3].gesture.acceleration", "a non-zero number (m/s^2)"},
        {"steady speed zero",
         [](Json& j) {
             j["trials"][0]["gesture"] = {{"type", "steady"}, {"speed", 0}};
         },
         "trials[0].gesture.speed", "a non-zero number (m/s)"},
        {"recorded without bowVelocity",
         [](Json& j)
         {
             j["channels"].erase(1);
             j["trials"][0]["gesture"] = {{"type", "recorded"}};
         },
         "trials[0].gesture.type", "a bowVelocity entry in \"channels\""},
        {"valid as text", [](Json& j) { j["trials"][0]["valid"] = "yes"; }, "trials[0].valid",
         "true or false"},
        {"repeat not integral", [](Json& j) { j["trials"][0]["repeat"] = 1.5; }, "trials[0].repeat",
         "an integer"},
        {"root is an array",
         [](Json& j) {
             j = Json::array({1, 2});
         },
         "", "a JSON object"},
    };
    return all;
}

TEST(MalformedDataset, EachCaseNamesFileFieldAndExpectation)
{
    for (const auto& c : cases())
    {
        SCOPED_TRACE(c.name);
        const DatasetError e = rejection(c);
        const std::string what = e.what();
        EXPECT_EQ(e.field(), c.field) << what;
        EXPECT_NE(e.expected().find(c.expected), std::string::npos) << what;
        if (*c.field)
            EXPECT_NE(what.find("field \"" + std::string(c.field) + "\""), std::string::npos) << what;
    }
}

TEST(MalformedDataset, MessagesReadWell)
{
    const auto message = [](const char* name)
    {
        for (const auto& c : cases())
            if (std::string(c.name) == name)
                return std::string(rejection(c).what());
        return std::string();
    };
    EXPECT_NE(message("acceleration missing")
                  .find("dataset.json: field \"trials[3].gesture.acceleration\": expected a non-zero number "
                        "(m/s^2) but got nothing (the field is required)"),
              std::string::npos);
    EXPECT_NE(message("bridgeForce in mN")
                  .find("dataset.json: field \"channels[0].unit\": expected \"N\" (the unit of bridgeForce) "
                        "but got \"mN\""),
              std::string::npos);
    EXPECT_NE(message("file outside the folder")
                  .find("field \"trials[0].file\": expected a path relative to the dataset folder, inside it "
                        "but got \"../x.wav\", a path that leaves the dataset folder"),
              std::string::npos);
}

TEST(MalformedDataset, NotJsonAtAll)
{
    test::DatasetFolder folder;
    folder.describe(std::string("RIFF\x01\x02 this is a WAV file, not JSON"));
    try
    {
        readDatasetDescription(folder.path());
        FAIL() << "accepted";
    }
    catch (const DatasetError& e)
    {
        EXPECT_EQ(e.file(), folder.descriptionPath());
        EXPECT_EQ(e.expected(), "valid JSON");
        EXPECT_NE(e.got().find("line 1"), std::string::npos) << e.what();
    }
}

TEST(MalformedDataset, EmptyFileAndMissingDescriptionAndMissingFolder)
{
    test::DatasetFolder folder;
    try
    {
        readDatasetDescription(folder.path());
        FAIL() << "accepted a folder without dataset.json";
    }
    catch (const DatasetError& e)
    {
        EXPECT_EQ(e.file(), folder.descriptionPath());
        EXPECT_EQ(e.got(), "no such file");
    }
    folder.describe(std::string());
    EXPECT_THROW(readDatasetDescription(folder.path()), DatasetError);
    try
    {
        readDatasetDescription(folder.path() + "/no-such-dataset");
        FAIL() << "accepted a missing folder";
    }
    catch (const DatasetError& e)
    {
        EXPECT_EQ(e.got(), "no such folder");
        EXPECT_NE(e.expected().find("a dataset folder"), std::string::npos);
    }
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::discovery
