// "rosin-preset/1": the shipped presets, name lookup, and every malformed case naming file, field,
// expectation.
#include <gtest/gtest.h>

#include <filesystem>

#include <cstdlib>

#include "core/config/ConfigError.h"
#include "core/config/PresetLoader.h"
#include "core/config/TempFiles.h"

namespace rosin::config
{
namespace ROSIN_FILE_LOCAL
{

// Sets ROSIN_PRESET_DIR for one test and restores it.
class ScopedPresetDir
{
  public:
    explicit ScopedPresetDir(const std::string& dir)
    {
        if (const char* old = std::getenv("ROSIN_PRESET_DIR"))
            old_ = old;
        setenv("ROSIN_PRESET_DIR", dir.c_str(), 1);
    }
    ~ScopedPresetDir()
    {
        if (old_.empty())
            unsetenv("ROSIN_PRESET_DIR");
        else
            setenv("ROSIN_PRESET_DIR", old_.c_str(), 1);
    }

  private:
    std::string old_;
};

TEST(PresetLoader, ShipsTheRequiredPresets)
{
    const auto names = presetNames();
    for (const char* required : {"galluzzo-rig", "schumacher-rig", "cello-plastic", "cello-classical",
                                 "cello-reconstructed", "cello-modified-bow", "violin-thermal"})
        EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
}

TEST(PresetLoader, EveryShippedPresetLoadsByName)
{
    for (const auto& name : presetNames())
    {
        SCOPED_TRACE(name);
        const Preset p = loadPreset(name);
        EXPECT_EQ(p.name, name); // "name" inside the file matches the file name
        EXPECT_FALSE(p.description.empty());
        EXPECT_EQ(p.source, resolvePresetPath(name));
    }
}

TEST(PresetLoader, GalluzzoRigFileMatchesTheBuiltInDefault)
{
    const Preset file = loadPreset("galluzzo-rig");
    const Preset builtIn = defaultPreset();
    EXPECT_EQ(file.string.name, "cello-D3");
    EXPECT_EQ(file.string.name, builtIn.string.name);
    EXPECT_EQ(file.string.tension, builtIn.string.tension);
    EXPECT_EQ(file.body, "cello");
    EXPECT_EQ(file.body, builtIn.body);
    EXPECT_EQ(file.friction, "plastic");
    EXPECT_EQ(file.friction, builtIn.friction);
    EXPECT_EQ(file.contact, "galluzzo");
    EXPECT_EQ(file.contact, builtIn.contact);
    EXPECT_EQ(file.beta, 0.0899);
    EXPECT_EQ(file.beta, builtIn.beta);
    EXPECT_EQ(file.torsion, builtIn.torsion);
    EXPECT_EQ(file.bendingStiffness, builtIn.bendingStiffness);
    EXPECT_EQ(file.ambientOffset, builtIn.ambientOffset);
}

TEST(PresetLoader, SchumacherRig)
{
    const Preset p = loadPreset("schumacher-rig");
    EXPECT_EQ(p.string.name, "violin-E5");
    EXPECT_EQ(p.body, "rigid");
    EXPECT_EQ(p.friction, "plastic");
    EXPECT_EQ(p.contact, "schumacher");
    EXPECT_EQ(p.beta, 0.127);
}

TEST(PresetLoader, PathsAndNames)
{
    EXPECT_EQ(resolvePresetPath("my.json"), "my.json");
    EXPECT_EQ(resolvePresetPath("presets/foo.json"), "presets/foo.json");
    EXPECT_EQ(resolvePresetPath("galluzzo-rig"), presetDirectory() + "/galluzzo-rig.json");
}

TEST(PresetLoader, EnvironmentOverridesThePresetFolder)
{
    test::TempDir dir;
    dir.write("mine.json", R"({"format":"rosin-preset/1","friction":"classical","beta":0.2})");
    ScopedPresetDir scoped(dir.path());
    EXPECT_EQ(presetDirectory(), dir.path());
    EXPECT_EQ(presetNames(), std::vector<std::string>{"mine"});
    const Preset p = loadPreset("mine");
    EXPECT_EQ(p.name, "mine"); // from the file name
    EXPECT_EQ(p.friction, "classical");
    EXPECT_EQ(p.beta, 0.2);
    EXPECT_EQ(p.body, "cello"); // absent fields keep the Galluzzo-rig defaults
}

TEST(PresetLoader, UnknownNameListsTheAvailablePresets)
{
    try
    {
        loadPreset("no-such-preset");
        FAIL();
    }
    catch (const ConfigError& e)
    {
        EXPECT_EQ(e.file(), presetDirectory() + "/no-such-preset.json");
        EXPECT_NE(e.expected().find("galluzzo-rig"), std::string::npos);
        EXPECT_NE(e.got().find("no-such-preset"), std::string::npos);
    }
}

// Found by fuzzing: a number beyond double's range escaped as nlohmann's out_of_range exception (a crash
// through std::terminate in the fuzz target); it is a JSON error naming the file like any other.
TEST(PresetLoader, NumberBeyondDoubleRangeIsAJsonErrorNamingTheFile)
{
    test::TempDir dir;
    const auto path = dir.write("huge.json", R"({"format":"rosin-preset/1","beta":1e3080})");
    try
    {
        loadPreset(path);
        FAIL() << "a number of 1e3080 was accepted";
    }
    catch (const ConfigError& e)
    {
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(e.expected(), "valid JSON");
        EXPECT_NE(e.got().find("number overflow parsing '1e3080'"), std::string::npos) << e.got();
    }
}

// Found by fuzzing: the message quoting a long bad value cut it inside a UTF-8 character, and writing the
// message threw instead of naming the field.
TEST(PresetLoader, LongNonAsciiValueIsQuotedInTheMessage)
{
    test::TempDir dir;
    std::string value;
    for (int i = 0; i < 40; ++i)
        value += "\xc3\xa9"; // e acute, two bytes
    const auto path =
        dir.write("accent.json", R"({"format":"rosin-preset/1","friction":")" + value + R"("})");
    try
    {
        loadPreset(path);
        FAIL() << "an unknown friction law was accepted";
    }
    catch (const ConfigError& e)
    {
        EXPECT_EQ(e.field(), "friction");
        EXPECT_NE(e.got().find("..."), std::string::npos) << e.got();
    }
}

TEST(PresetLoader, InlineStringObjects)
{
    test::TempDir dir;
    const auto based = dir.write("a.json", R"({"format":"rosin-preset/1",
        "string":{"base":"cello-D3","name":"cello-D3-heavy","tension":130,"lossA":0.2}})");
    const Preset a = loadPreset(based);
    EXPECT_EQ(a.string.name, "cello-D3-heavy");
    EXPECT_EQ(a.string.tension, 130.0);
    EXPECT_EQ(a.string.lossA, 0.2);
    EXPECT_EQ(a.string.massPerLength, 2.7e-3); // from the base

    const auto custom = dir.write("b.json", R"({"format":"rosin-preset/1",
        "string":{"tension":60,"massPerLength":0.001,"length":0.5,"torsionalQ":20},
        "contact":{"base":"schumacher","radius":3e-4,"scaling":"hertz"},"torsion":false,"ambientOffset":-5})");
    const Preset b = loadPreset(custom);
    EXPECT_EQ(b.string.tension, 60.0);
    EXPECT_EQ(b.string.length, 0.5);
    EXPECT_EQ(b.string.torsionalQ, 20.0);
    EXPECT_EQ(b.contact, "schumacher");
    EXPECT_EQ(*b.contactOverrides.radius, 3e-4);
    EXPECT_EQ(*b.contactOverrides.scaling, physics::ContactScaling::Hertz);
    EXPECT_FALSE(b.contactOverrides.layerThickness.has_value());
    EXPECT_FALSE(b.torsion);
    EXPECT_EQ(b.ambientOffset, -5.0);
}

// The plugin's level and measured body response of a program: the level as given, the response's path
// resolved against the preset's own folder (so a preset and its response travel together).
TEST(PresetLoader, OutputLevelAndBodyResponseRelativeToThePreset)
{
    test::TempDir dir;
    dir.write("ir.wav", "RIFF"); // existence is what the loader checks; the plugin reads the audio
    const auto path =
        dir.write("p.json", R"({"format":"rosin-preset/1","outputLevel":-3.5,"bodyResponse":"ir.wav"})");
    const Preset p = loadPreset(path);
    ASSERT_TRUE(p.outputLevel.has_value());
    EXPECT_EQ(*p.outputLevel, -3.5);
    ASSERT_TRUE(p.bodyResponse.has_value());
    EXPECT_EQ(
        std::filesystem::path(*p.bodyResponse),
        std::filesystem::absolute(std::filesystem::path(path).parent_path() / "ir.wav").lexically_normal());
    EXPECT_FALSE(loadPreset("cello-plastic").bodyResponse.has_value()); // Rosin ships no measured data
}

struct BadPreset
{
    const char* name;
    const char* json;
    const char* field;
    const char* expected;
};

class PresetErrors : public ::testing::TestWithParam<BadPreset>
{
};

TEST_P(PresetErrors, NameFileFieldAndExpectation)
{
    const BadPreset& bad = GetParam();
    test::TempDir dir;
    const auto path = dir.write(std::string(bad.name) + ".json", bad.json);
    try
    {
        loadPreset(path);
        FAIL() << bad.name << " was accepted";
    }
    catch (const ConfigError& e)
    {
        const std::string what = e.what();
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(e.field(), bad.field) << what;
        EXPECT_NE(e.expected().find(bad.expected), std::string::npos) << what;
        EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
    }
}

#define P(body) R"({"format":"rosin-preset/1",)" body "}"
INSTANTIATE_TEST_SUITE_P(
    Malformed, PresetErrors,
    ::testing::Values(
        BadPreset{"syntax", R"({"format":"rosin-preset/1",})", "", "valid JSON"},
        BadPreset{"empty", "", "", "valid JSON"}, BadPreset{"array", "[]", "", "a JSON object"},
        BadPreset{"noFormat", R"({"friction":"plastic"})", "format", "rosin-preset/1"},
        BadPreset{"formatNumber", R"({"format":1})", "format", "rosin-preset/1"},
        BadPreset{"gestureFormat", R"({"format":"rosin-gesture/1"})", "format", "rosin-preset/1"},
        BadPreset{"friction", P(R"("friction":"plasticc")"), "friction",
                  "one of classical, reconstructed, plastic, viscous, modified-bow, modified-rod"},
        BadPreset{"frictionNumber", P(R"("friction":3)"), "friction", "one of classical"},
        BadPreset{"body", P(R"("body":"viola")"), "body", "one of cello, violin, rigid"},
        BadPreset{"outputLevel", P(R"("outputLevel":20)"), "outputLevel", "-60..12"},
        BadPreset{"bodyResponseMissing", P(R"("bodyResponse":"no-such.wav")"), "bodyResponse",
                  "an existing audio file"},
        BadPreset{"stringName", P(R"("string":"cello-X9")"), "string", "cello-D3"},
        BadPreset{"stringArray", P(R"("string":[1])"), "string", "a catalogue name or a string object"},
        BadPreset{"stringBase", P(R"("string":{"base":"nope"})"), "string.base", "violin-E5"},
        BadPreset{"stringMissing", P(R"("string":{"tension":100,"length":0.7})"), "string.massPerLength",
                  "required when \"base\" is absent"},
        BadPreset{"stringTension", P(R"("string":{"base":"cello-D3","tension":-1})"), "string.tension",
                  "1..5000"},
        BadPreset{"stringLength", P(R"("string":{"base":"cello-D3","length":690})"), "string.length",
                  "0.05..3"},
        BadPreset{"stringUnknown", P(R"("string":{"base":"cello-D3","tensoin":100})"), "string.tensoin",
                  "known fields"},
        BadPreset{"contactName", P(R"("contact":"woodhouse")"), "contact", "one of galluzzo, schumacher"},
        BadPreset{"contactType", P(R"("contact":2)"), "contact", "or an object"},
        BadPreset{"contactRadius", P(R"("contact":{"radius":0.5})"), "contact.radius", "1e-06..0.01"},
        BadPreset{"contactForce", P(R"("contact":{"referenceForce":0})"), "contact.referenceForce",
                  "0.001..100"},
        BadPreset{"contactLayer", P(R"("contact":{"layerThickness":"1um"})"), "contact.layerThickness",
                  "1e-09"},
        BadPreset{"contactScaling", P(R"("contact":{"scaling":"linear"})"), "contact.scaling",
                  "coulomb, hertz"},
        BadPreset{"contactBase", P(R"("contact":{"base":"x"})"), "contact.base", "galluzzo"},
        BadPreset{"torsion", P(R"("torsion":"yes")"), "torsion", "true or false"},
        BadPreset{"bending", P(R"("bendingStiffness":1)"), "bendingStiffness", "true or false"},
        BadPreset{"ambient", P(R"("ambientOffset":500)"), "ambientOffset", "-50..100"},
        BadPreset{"betaHigh", P(R"("beta":0.6)"), "beta", "0.01..0.5"},
        BadPreset{"betaNull", P(R"("beta":null)"), "beta", "0.01..0.5"},
        BadPreset{"nameNumber", P(R"("name":7)"), "name", "a string"},
        BadPreset{"unknown", P(R"("frcition":"plastic")"), "frcition", "known fields"}),
    [](const auto& info) { return std::string(info.param.name); });
#undef P

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::config
