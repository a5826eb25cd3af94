// Presets with a "rig" ([Smith2000]'s oscillator rig): the shipped cantilever preset carries [Smith2000]'s
// rig and the calibrated values, and every bad rig field is named with its expectation.
#include <gtest/gtest.h>

#include "core/config/ConfigError.h"
#include "core/config/PresetLoader.h"
#include "core/config/TempFiles.h"
#include "core/config/VoiceSetup.h"
#include "core/physics/rig/CantileverContact.h"

namespace rosin::config
{
namespace ROSIN_FILE_LOCAL
{

TEST(RigPreset, CantileverIsTheRosinTribologyRig)
{
    const Preset p = loadPreset("cantilever");
    ASSERT_TRUE(p.rig.has_value());
    EXPECT_DOUBLE_EQ(p.rig->oscillator.frequency, 108.0);    // [Smith2000]: first bending mode
    EXPECT_DOUBLE_EQ(p.rig->oscillator.qualityFactor, 20.0); // [Smith2000]: Q 20
    EXPECT_DOUBLE_EQ(p.rig->normalForce, 6.3);               // [Smith2000] Fig. 2
    EXPECT_DOUBLE_EQ(p.rig->rodSpeed, 0.042);
    // The calibrated mass of OscillatorRigParameters (tests/core/physics/rig/TraditionalCurveRigTest.cpp
    // reproduces it).
    EXPECT_DOUBLE_EQ(p.rig->oscillator.modalMass, physics::OscillatorRigParameters{}.modalMass);
    EXPECT_EQ(p.friction, "classical"); // eq. 2, the traditional curve
    const VoiceSetup s = buildVoiceSetup(p);
    const physics::ContactParameters c = physics::cantileverContact();
    EXPECT_DOUBLE_EQ(s.contact.rig.radius, c.rig.radius);
    EXPECT_DOUBLE_EQ(s.contact.calibration.radius, c.rig.radius);
}

TEST(RigPreset, ContactOverridesKeepTheCalibrationOnTheRig)
{
    test::TempDir dir;
    const auto path = dir.write("r.json", R"({"format":"rosin-preset/1","rig":{"type":"oscillator"},
        "contact":{"base":"cantilever","radius":0.001}})");
    const VoiceSetup s = buildVoiceSetup(loadPreset(path));
    EXPECT_DOUBLE_EQ(s.contact.rig.radius, 0.001);
    EXPECT_DOUBLE_EQ(s.contact.calibration.radius, 0.001);
}

TEST(RigPreset, PresetsWithoutRigHaveNone)
{
    EXPECT_FALSE(loadPreset("galluzzo-rig").rig.has_value());
}

struct BadRig
{
    const char* json;
    const char* field;
    const char* expected;
};

class RigPresetErrors : public ::testing::TestWithParam<BadRig>
{
};

TEST_P(RigPresetErrors, NameFileFieldAndExpectation)
{
    const BadRig& bad = GetParam();
    test::TempDir dir;
    const auto path =
        dir.write("bad-rig.json", std::string(R"({"format":"rosin-preset/1","rig":)") + bad.json + "}");
    try
    {
        loadPreset(path);
        FAIL() << bad.json << " was accepted";
    }
    catch (const ConfigError& e)
    {
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(e.field(), bad.field) << e.what();
        EXPECT_NE(e.expected().find(bad.expected), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, RigPresetErrors,
    ::testing::Values(BadRig{"3", "rig", "object"}, BadRig{R"({"frequency":108})", "rig.type", "oscillator"},
                      BadRig{R"({"type":"string"})", "rig.type", "oscillator"},
                      BadRig{R"({"type":"oscillator","frequency":0})", "rig.frequency", "Hz"},
                      BadRig{R"({"type":"oscillator","modalMass":220})", "rig.modalMass", "kg"},
                      BadRig{R"({"type":"oscillator","modalMass":"heavy"})", "rig.modalMass", "number"},
                      BadRig{R"({"type":"oscillator","qualityFactor":0.1})", "rig.qualityFactor", "0.6"},
                      BadRig{R"({"type":"oscillator","normalForce":63})", "rig.normalForce", "N"},
                      BadRig{R"({"type":"oscillator","mass":0.02})", "rig.mass", ""}));

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::config
