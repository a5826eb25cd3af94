// MPE through the whole processor, judged from the rendered audio: after the MPE Configuration Message, a
// per-note pitch bend on one member channel moves only that note's pitch (its string's finger), while a note
// on another member channel keeps its own. Expected pitches are equal-tempered note frequencies.
#include <gtest/gtest.h>

#include <cstdio>

#include "instrument/player/StringChoice.h"
#include "instrument/plugin/PluginTestSupport.h"
#include "support/Spectrum.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

constexpr double kFs = 48000.0;

void addController(juce::MidiMessageSequence& seq, int channel, int cc, int value)
{
    seq.addEvent(juce::MidiMessage::controllerEvent(channel, cc, value), 0.0);
}

TEST(PluginMpe, PerNoteBendMovesOnlyItsOwnNote)
{
    plugin::RosinProcessor p;
    p.setProgramByName("cello-plastic");
    setParameter(p, plugin::ids::bowForce, 0.5f);
    setParameter(p, plugin::ids::beta, 0.1f);
    setParameter(p, plugin::ids::outputLevel, 0.0f);
    juce::MidiMessageSequence seq;
    // MPE Configuration Message: RPN 6 on the master channel, 15 member channels.
    addController(seq, 1, 101, 0);
    addController(seq, 1, 100, 6);
    addController(seq, 1, 6, 15);
    // Channel 2: D3 bent up two semitones (member range +-48); channel 3: A3, no bend.
    seq.addEvent(juce::MidiMessage::pitchWheel(2, 8192 + 8192 * 2 / 48), 0.0);
    seq.addEvent(juce::MidiMessage::noteOn(2, 50, static_cast<juce::uint8>(90)), 0.001);
    seq.addEvent(juce::MidiMessage::noteOn(3, 57, static_cast<juce::uint8>(90)), 0.001);
    seq.addEvent(juce::MidiMessage::noteOff(2, 50), 1.6);
    seq.addEvent(juce::MidiMessage::noteOff(3, 57), 1.6);
    engine::MidiRenderSettings settings;
    settings.sampleRate = kFs;
    settings.tailSeconds = 0.0;
    const auto r = test::renderMidi(p, seq, settings);
    ASSERT_TRUE(allFinite(r.audio));

    const std::vector<double> x(r.audio.begin(), r.audio.end());
    const auto mag =
        hannSpectrum(x, static_cast<std::size_t>(0.7 * kFs), static_cast<std::size_t>(0.8 * kFs), 1u << 18);
    const double bin = kFs / static_cast<double>(1u << 18);
    const auto near = [&](double f) { return findPeak(mag, bin, f * 0.985, f * 1.015); };
    const Peak bent = near(player::noteFrequency(52)), open = near(player::noteFrequency(57));
    const Peak unbent = near(player::noteFrequency(50));
    std::printf("[figure] MPE: bent D3 -> %.2f Hz (E3 %.2f, %+.2f cents), A3 %.2f Hz (%+.2f cents), level at "
                "unbent D3 %.1f dB below the bent note\n",
                bent.frequency, player::noteFrequency(52), cents(bent.frequency, player::noteFrequency(52)),
                open.frequency, cents(open.frequency, player::noteFrequency(57)),
                20.0 * std::log10(bent.magnitude / unbent.magnitude));
    EXPECT_LT(std::abs(cents(bent.frequency, player::noteFrequency(52))), 5.0);
    EXPECT_LT(std::abs(cents(open.frequency, player::noteFrequency(57))), 5.0);
    EXPECT_GT(bent.magnitude, 10.0 * unbent.magnitude); // nothing left at the unbent pitch
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
