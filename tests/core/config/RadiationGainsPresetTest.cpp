// A program's radiation gains ("radiationGains", Resources/docs/presets.md): read in order, applied to the
// body a preset builds, and refused with the field and what was expected when malformed.
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

std::string presetWithGains(const std::string& gains)
{
    return R"({"format":"rosin-preset/1","radiationGains":)" + gains + "}";
}

TEST(RadiationGainsPreset, PointsAreReadAndAppliedToTheBody)
{
    test::TempDir dir;
    const auto path = dir.write("fitted.json", presetWithGains(R"([{"hz":200,"db":-3},{"hz":2000,"db":6}])"));
    const Preset p = loadPreset(path);
    ASSERT_EQ(p.radiationGains.size(), 2u);
    EXPECT_EQ(p.radiationGains[1].frequencyHz, 2000.0);
    EXPECT_EQ(p.radiationGains[1].gainDb, 6.0);
    const VoiceSetup setup = buildVoiceSetup(p);
    for (const auto& m : setup.voice.body.modes)
    {
        const double expected = m.frequency <= 200.0    ? -3.0
                                : m.frequency >= 2000.0 ? 6.0
                                                        : -3.0 + 9.0 * std::log10(m.frequency / 200.0);
        EXPECT_NEAR(20.0 * std::log10(m.radiationGain), expected, 1e-9) << m.frequency;
    }
    EXPECT_TRUE(loadPreset(dir.write("plain.json", R"({"format":"rosin-preset/1"})")).radiationGains.empty());
}

struct Malformed
{
    const char* gains;
    const char* field;
    const char* expected; ///< part of what the message says was expected
};

TEST(RadiationGainsPreset, MalformedGainsNameTheFieldAndWhatWasExpected)
{
    const Malformed cases[] = {
        {R"({"hz":100})", "radiationGains", "non-empty array"},
        {R"([])", "radiationGains", "non-empty array"},
        {R"([{"hz":100,"db":1},{"hz":100,"db":2}])", "radiationGains[1].hz", "above the previous"},
        {R"([{"hz":10,"db":1}])", "radiationGains[0].hz", "20"},
        {R"([{"hz":100,"db":40}])", "radiationGains[0].db", "30"},
        {R"([{"hz":100}])", "radiationGains[0].db", ""},
        {R"([{"hz":100,"db":1,"q":2}])", "radiationGains[0].q", ""},
        {R"([3])", "radiationGains[0]", "object"},
    };
    test::TempDir dir;
    for (const auto& c : cases)
        test::expectPresetRefused(dir.write("bad.json", presetWithGains(c.gains)), c.field, c.expected,
                                  c.gains);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::config
