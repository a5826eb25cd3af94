// A preset's bow ("bow", Resources/docs/presets.md): read into the voice it builds, the seeds' rigid point
// when absent, and refused with the field and what was expected when malformed.
#include <gtest/gtest.h>

#include <string>

#include "core/config/PresetLoader.h"
#include "core/config/RefusedPreset.h"
#include "core/config/TempFiles.h"
#include "core/config/VoiceSetup.h"

namespace rosin::config
{
namespace ROSIN_FILE_LOCAL
{

std::string presetWithBow(const std::string& bow)
{
    return R"({"format":"rosin-preset/1","bow":)" + bow + "}";
}

TEST(BowPreset, WidthAndHairReachTheVoice)
{
    test::TempDir dir;
    const auto hair = buildVoiceSetup(
        loadPreset(dir.write("a.json", presetWithBow(R"({"width":0.008,"hair":"horsehair"})"))));
    EXPECT_EQ(hair.voice.bow.width, 0.008);
    EXPECT_TRUE(hair.voice.bow.compliantHair);
    EXPECT_EQ(hair.voice.bow.hairStiffness, physics::horsehairBow(0.0).hairStiffness);
    const auto soft = loadPreset(dir.write("b.json", presetWithBow(R"({"hairStiffness":5000})"))).bow;
    EXPECT_TRUE(soft.compliantHair);
    EXPECT_EQ(soft.hairStiffness, 5000.0);
    EXPECT_EQ(soft.hairDamping, physics::horsehairBow(0.0).hairDamping);
    const auto ribbon = loadPreset(dir.write("c.json", presetWithBow(R"({"width":0.01})"))).bow;
    EXPECT_EQ(ribbon.width, 0.01);
    EXPECT_FALSE(ribbon.compliantHair);
    const auto plain = loadPreset(dir.write("d.json", R"({"format":"rosin-preset/1"})")).bow;
    EXPECT_EQ(plain.width, 0.0);
    EXPECT_FALSE(plain.compliantHair);
    EXPECT_EQ(plain.slipNoise, 0.0);
}

TEST(BowPreset, SlipNoiseIsANumberOrTheRibbonsEstimate)
{
    test::TempDir dir;
    const auto given = loadPreset(dir.write("a.json", presetWithBow(R"({"slipNoise":0.2})"))).bow;
    EXPECT_EQ(given.slipNoise, 0.2);
    EXPECT_FALSE(given.compliantHair);
    const auto ribbon = buildVoiceSetup(
        loadPreset(dir.write("b.json", presetWithBow(R"({"slipNoise":"ribbon","hair":"horsehair"})"))));
    EXPECT_EQ(ribbon.voice.bow.slipNoise, physics::ribbonSlipNoise());
    EXPECT_TRUE(ribbon.voice.bow.compliantHair);
    // 50 hairs on the string (BowParameters.cpp): 1 / sqrt(50).
    EXPECT_NEAR(physics::ribbonSlipNoise(), 0.1414, 1e-4);
}

struct Malformed
{
    const char* bow;
    const char* field;
    const char* expected; ///< part of what the message says was expected
};

TEST(BowPreset, MalformedBowNamesTheFieldAndWhatWasExpected)
{
    const Malformed cases[] = {
        {R"({"width":0.1})", "bow.width", "0.03"},
        {R"({"width":-0.001})", "bow.width", "0"},
        {R"({"hair":"nylon"})", "bow.hair", "horsehair"},
        {R"({"hair":"rigid","hairStiffness":5000})", "bow.hair", "horsehair"},
        {R"({"hairDamping":0})", "bow.hairDamping", "0.1"},
        {R"({"tilt":30})", "bow.tilt", ""},
        {R"({"slipNoise":0.9})", "bow.slipNoise", "0.5"},
        {R"({"slipNoise":"rough"})", "bow.slipNoise", "ribbon"},
        {R"(8)", "bow", "object"},
    };
    test::TempDir dir;
    for (const auto& c : cases)
        test::expectPresetRefused(dir.write("bad.json", presetWithBow(c.bow)), c.field, c.expected, c.bow);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::config
