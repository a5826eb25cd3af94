// Every factory preset plays the demo phrase at 44.1, 48 and 96 kHz with finite, bounded output and no
// runaway. Bounded means within the output sanitiser's clamp; how often the clamp engaged is printed, not
// asserted: the viscous law drags the string with a large quasi-static force and reaches it at the default
// level.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "core/config/PresetLoader.h"
#include "instrument/engine/SoftClip.h"
#include "instrument/plugin/PluginTestSupport.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

class PresetRender : public ::testing::TestWithParam<std::string>
{
};

TEST_P(PresetRender, DemoPhraseIsFiniteAndBoundedAtThreeSampleRates)
{
    for (double fs : {44100.0, 48000.0, 96000.0})
    {
        const auto r = renderDemo(GetParam(), fs, 512, 0.3);
        EXPECT_TRUE(allFinite(r.audio)) << fs;
        EXPECT_EQ(r.nonFiniteSamples, 0) << fs;
        EXPECT_LE(r.peak, 1.0f) << fs;
        EXPECT_EQ(r.runawayResets, 0) << GetParam() << " at " << fs << " Hz";
        const auto clamped =
            std::count_if(r.audio.begin(), r.audio.end(), [](float y) { return std::abs(y) >= 1.0f; });
        EXPECT_GT(r.peak, 1e-3f) << GetParam() << " at " << fs << " Hz is silent";
        std::printf(
            "[ figures  ] %-20s %6.0f Hz: peak %.4f (%.1f dBFS), clamped samples %ld, runaway resets %d\n",
            GetParam().c_str(), fs, r.peak, 20.0 * std::log10(std::max(1e-9f, r.peak)),
            static_cast<long>(clamped), r.runawayResets);
    }
}

// Levels: the mezzo-forte demo phrase (velocities 80-110) peaks near -6 dBFS with every program, below the
// soft clip's knee (-1.9 dBFS). Violin programs play it a twelfth up (+19 semitones: its C2-D4 become G3-A4,
// inside the violin's range). The programs' output levels are calibrations made for this (presets/*.json
// "outputLevel"); the test checks that they hold, within +-1.5 dB.
TEST_P(PresetRender, MezzoFortePhrasePeaksNearMinusSixDbfsBelowTheClip)
{
    plugin::RosinProcessor processor;
    processor.setProgramByName(GetParam());
    const bool violin = engine::instrumentIndexForPreset(config::loadPreset(GetParam())) == 1;
    juce::MidiMessageSequence phrase = demoPhrase();
    for (int i = 0; violin && i < phrase.getNumEvents(); ++i)
        if (auto& m = phrase.getEventPointer(i)->message; m.isNoteOnOrOff())
            m.setNoteNumber(m.getNoteNumber() + 19);
    engine::MidiRenderSettings settings;
    settings.sampleRate = 48000.0;
    settings.tailSeconds = 1.0;
    const auto r = test::renderMidi(processor, phrase, settings);
    const double dbfs = 20.0 * std::log10(std::max(1e-9f, r.peak));
    std::printf("[ figures  ] %-20s phrase peak %.2f dBFS\n", GetParam().c_str(), dbfs);
    EXPECT_NEAR(dbfs, -6.0, 1.5) << GetParam();
    EXPECT_LT(r.peak, engine::kSoftClipKnee) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(FactoryPresets, PresetRender, ::testing::ValuesIn(instrumentPresetNames()),
                         [](const auto& info)
                         {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return name;
                         });

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
