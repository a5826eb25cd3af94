// "rosin-gesture/1" scripts: a valid script round trip, and every malformed case naming file, field,
// expectation.
#include <gtest/gtest.h>

#include "core/config/ConfigError.h"
#include "core/config/GestureScriptLoader.h"
#include "core/config/TempFiles.h"
#include "core/gesture/BowGesture.h"

namespace rosin::config
{
namespace ROSIN_FILE_LOCAL
{

TEST(GestureScriptLoader, ReadsTheDocumentedExample)
{
    test::TempDir dir;
    const auto path = dir.write("g.json", R"({
      "format": "rosin-gesture/1",
      "description": "attack, then slow the bow down",
      "segments": [
        {"seconds": 0.5, "force": {"from": 0.5, "to": 1.0}, "speed": 0.1, "beta": 0.1, "finger": 1.0,
         "label": "attack"},
        {"seconds": 1, "acceleration": -0.2, "force": {"to": 0.3}},
        {"seconds": 0.25, "speed": {"to": 0}}
      ]})");
    const auto script = loadGestureScript(path);
    ASSERT_EQ(script.segments.size(), 3u);
    const auto& a = script.segments[0];
    EXPECT_EQ(a.seconds, 0.5);
    EXPECT_EQ(*a.force->from, 0.5);
    EXPECT_EQ(a.force->to, 1.0);
    EXPECT_EQ(*a.speed->from, 0.1); // a number is a constant
    EXPECT_EQ(a.speed->to, 0.1);
    const auto& b = script.segments[1];
    EXPECT_EQ(*b.acceleration, -0.2);
    EXPECT_FALSE(b.force->from.has_value());
    EXPECT_FALSE(b.beta.has_value());
    EXPECT_DOUBLE_EQ(script.totalSeconds(), 1.75);

    gesture::BowGesture g;
    g.prepare(script, gesture::GestureStart{}, 1000.0, 0.0);
    EXPECT_EQ(g.totalSamples(), 1750);
    for (int k = 0; k < 500; ++k)
        g.next();
    const auto in = g.next(); // first sample of the deceleration
    EXPECT_DOUBLE_EQ(in.bowVelocity, 0.1);
    EXPECT_DOUBLE_EQ(in.bowForce, 1.0);
}

TEST(GestureScriptLoader, FirstSegmentFallsBackToTheStartValues)
{
    test::TempDir dir;
    const auto path =
        dir.write("g.json", R"({"format":"rosin-gesture/1","segments":[{"seconds":0.1,"speed":0.1}]})");
    gesture::GestureStart start;
    start.beta = 0.127;
    const auto script = loadGestureScript(path, start);
    gesture::BowGesture g;
    g.prepare(script, start, 1000.0);
    const auto in = g.next();
    EXPECT_EQ(in.beta, 0.127);
    EXPECT_EQ(in.bowForce, 1.0);
    EXPECT_EQ(in.fingerRatio, 1.0);
}

struct BadScript
{
    const char* name;
    const char* json;
    const char* field;    // "" for whole-file errors
    const char* expected; // fragment
};

class GestureScriptErrors : public ::testing::TestWithParam<BadScript>
{
};

TEST_P(GestureScriptErrors, NameFileFieldAndExpectation)
{
    const BadScript& bad = GetParam();
    test::TempDir dir;
    const auto path = dir.write(std::string(bad.name) + ".json", bad.json);
    try
    {
        loadGestureScript(path);
        FAIL() << bad.name << " was accepted";
    }
    catch (const ConfigError& e)
    {
        const std::string what = e.what();
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(e.field(), bad.field) << what;
        EXPECT_NE(e.expected().find(bad.expected), std::string::npos) << what;
        EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
        if (*bad.field)
        {
            EXPECT_NE(what.find("field \"" + std::string(bad.field) + "\": expected "), std::string::npos)
                << what;
        }
    }
}

#define SEG(body) R"({"format":"rosin-gesture/1","segments":[)" body "]}"
INSTANTIATE_TEST_SUITE_P(
    Malformed, GestureScriptErrors,
    ::testing::Values(
        BadScript{"syntax", R"({"format": "rosin-gesture/1", "segments": [)", "", "valid JSON"},
        BadScript{"notObject", "[1,2]", "", "a JSON object"},
        BadScript{"noFormat", R"({"segments":[{"seconds":1}]})", "format", "rosin-gesture/1"},
        BadScript{"wrongFormat", R"({"format":"rosin-gesture/2","segments":[{"seconds":1}]})", "format",
                  "rosin-gesture/1"},
        BadScript{"presetFormat", R"({"format":"rosin-preset/1"})", "format", "rosin-gesture/1"},
        BadScript{"noSegments", R"({"format":"rosin-gesture/1"})", "segments", "non-empty array"},
        BadScript{"emptySegments", R"({"format":"rosin-gesture/1","segments":[]})", "segments",
                  "non-empty array"},
        BadScript{"unknownTop", R"({"format":"rosin-gesture/1","segmnts":[]})", "segmnts", "known fields"},
        BadScript{"segmentNotObject", SEG("3"), "segments[0]", "a JSON object"},
        BadScript{"noSeconds", SEG(R"({"speed":0.1})"), "segments[0].seconds", "> 0 and <= 600"},
        BadScript{"zeroSeconds", SEG(R"({"seconds":0})"), "segments[0].seconds", "> 0 and <= 600"},
        BadScript{"longSeconds", SEG(R"({"seconds":601})"), "segments[0].seconds", "> 0 and <= 600"},
        BadScript{"totalTooLong", SEG(R"({"seconds":400},{"seconds":400})"), "segments", "at most 600 s"},
        BadScript{"secondsString", SEG(R"({"seconds":"1"})"), "segments[0].seconds", "a number"},
        BadScript{"forceHigh", SEG(R"({"seconds":1,"force":21})"), "segments[0].force", "0..20"},
        BadScript{"forceNegative", SEG(R"({"seconds":1,"force":{"from":-1,"to":1}})"),
                  "segments[0].force.from", "0..20"},
        BadScript{"forceRampNoTo", SEG(R"({"seconds":1,"force":{"from":1}})"), "segments[0].force.to",
                  "0..20"},
        BadScript{"forceRampExtra", SEG(R"({"seconds":1,"force":{"from":1,"to":2,"via":3}})"),
                  "segments[0].force.via", "known fields from, to"},
        BadScript{"forceString", SEG(R"({"seconds":1,"force":"loud"})"), "segments[0].force", "or a ramp"},
        BadScript{"speedHigh", SEG(R"({"seconds":1},{"seconds":1,"speed":{"to":5.5}})"),
                  "segments[1].speed.to", "-5..5"},
        BadScript{"accelerationHigh", SEG(R"({"seconds":0.01,"acceleration":60})"),
                  "segments[0].acceleration", "-50..50"},
        BadScript{"accelerationRamp", SEG(R"({"seconds":0.01,"acceleration":{"to":1}})"),
                  "segments[0].acceleration", "-50..50"},
        BadScript{"accelerationOverspeed", SEG(R"({"seconds":1,"speed":4},{"seconds":1,"acceleration":2})"),
                  "segments[1].acceleration", "within -5..5 m/s"},
        BadScript{"speedAndAcceleration", SEG(R"({"seconds":1,"speed":0.1,"acceleration":1})"),
                  "segments[0].acceleration", "not both"},
        BadScript{"betaLow", SEG(R"({"seconds":1,"beta":0.001})"), "segments[0].beta", "0.01..0.5"},
        BadScript{"fingerHigh", SEG(R"({"seconds":1,"finger":{"from":1,"to":1.5}})"), "segments[0].finger.to",
                  "0.1..1"},
        BadScript{"unknownSegmentField", SEG(R"({"seconds":1,"froce":1})"), "segments[0].froce",
                  "known fields"},
        BadScript{"labelNumber", SEG(R"({"seconds":1,"label":3})"), "segments[0].label", "a string"}),
    [](const auto& info) { return std::string(info.param.name); });
#undef SEG

TEST(GestureScriptLoader, MissingFileIsNamed)
{
    try
    {
        loadGestureScript("/nonexistent/gesture.json");
        FAIL();
    }
    catch (const ConfigError& e)
    {
        EXPECT_EQ(e.file(), "/nonexistent/gesture.json");
        EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos);
    }
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::config
