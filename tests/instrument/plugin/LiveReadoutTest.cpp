// The editor's live readout comes from the lab's live regime meter: a held D3 on the cello through the
// processor reads as bowed Helmholtz motion, with about one flyback per period; after note-off (bow
// lifted) the string reads as not bowed.
#include <gtest/gtest.h>

#include <juce_audio_processors/juce_audio_processors.h>

#include "instrument/plugin/RosinProcessor.h"

namespace ROSIN_FILE_LOCAL
{
using namespace rosin;
constexpr double kFs = 48000.0;
constexpr int kBlock = 256;

void play(plugin::RosinProcessor& p, juce::MidiBuffer& midi, double seconds)
{
    juce::AudioBuffer<float> buffer(2, kBlock);
    for (int b = 0; b < static_cast<int>(seconds * kFs / kBlock); ++b)
    {
        p.processBlock(buffer, midi);
        midi.clear();
    }
}

// The string sounding `hz`, or -1.
int stringPlaying(const plugin::Telemetry& t, double hz)
{
    for (int s = 0; s < t.stringCount.load(); ++s)
        if (std::abs(t.strings[static_cast<std::size_t>(s)].read().frequency - hz) < 0.01 * hz)
            return s;
    return -1;
}

TEST(LiveReadout, HeldNoteReadsAsHelmholtzThenSilent)
{
    plugin::RosinProcessor p;
    p.setPlayConfigDetails(0, 2, kFs, kBlock);
    p.prepareToPlay(kFs, kBlock);
    juce::MidiBuffer midi;
    midi.addEvent(juce::MidiMessage::noteOn(1, 50, 0.8f), 0); // D3, the open D string
    play(p, midi, 1.5);
    const int s = stringPlaying(p.telemetry(), 146.83);
    ASSERT_GE(s, 0);
    const auto r = p.telemetry().strings[static_cast<std::size_t>(s)].read();
    EXPECT_TRUE(r.bowing);
    EXPECT_EQ(r.regime, analysis::Regime::Helmholtz)
        << plugin::regimeDisplayName(r.regime, r.bowing) << " fpp " << r.flybacksPerPeriod << " slips "
        << r.slipsPerPeriod << " cv " << r.irregularity << " stick " << r.stickFraction;
    EXPECT_NEAR(r.flybacksPerPeriod, 1.0, 0.2);

    midi.addEvent(juce::MidiMessage::noteOff(1, 50), 0);
    play(p, midi, 1.0);
    const auto after = p.telemetry().strings[static_cast<std::size_t>(s)].read();
    EXPECT_FALSE(after.bowing);
    EXPECT_STREQ(plugin::regimeDisplayName(after.regime, after.bowing), "silent");
}

} // namespace ROSIN_FILE_LOCAL
