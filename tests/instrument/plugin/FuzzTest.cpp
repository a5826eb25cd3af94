// Random automation of every parameter and random MIDI for 10 s of audio: finite output, never above the
// clamp, and no state that stays broken (the last second, after all notes are lifted, decays).
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "instrument/plugin/PluginTestSupport.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

juce::MidiMessage randomMessage(std::mt19937& rng)
{
    std::uniform_int_distribution<int> kind(0, 9), note(24, 108), value(0, 127), bend(0, 16383);
    const std::array<int, 6> controllers = {1, 2, 11, 21, 64, 121};
    switch (kind(rng))
    {
    case 0:
    case 1:
    case 2:
        return juce::MidiMessage::noteOn(1, note(rng), static_cast<juce::uint8>(std::max(1, value(rng))));
    case 3:
    case 4:
        return juce::MidiMessage::noteOff(1, note(rng));
    case 5:
        return juce::MidiMessage::controllerEvent(1, controllers[static_cast<std::size_t>(value(rng)) % 6],
                                                  value(rng));
    case 6:
        return juce::MidiMessage::channelPressureChange(1, value(rng));
    case 7:
        return juce::MidiMessage::aftertouchChange(1, note(rng), value(rng));
    case 8:
        return juce::MidiMessage::pitchWheel(1, bend(rng));
    default:
        return juce::MidiMessage::noteOn(1, note(rng), static_cast<juce::uint8>(0)); // velocity-0 note-off
    }
}

TEST(PluginFuzz, RandomAutomationAndMidiForTenSecondsStayFiniteAndBounded)
{
    constexpr double kFs = 48000.0;
    constexpr int kBlock = 256;
    const int blocks = static_cast<int>(10.0 * kFs / kBlock);
    std::mt19937 rng(20261122);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);

    plugin::RosinProcessor p;
    p.setPlayConfigDetails(0, 2, kFs, kBlock);
    p.prepareToPlay(kFs, kBlock);
    juce::AudioBuffer<float> buffer(2, kBlock);
    juce::MidiBuffer midi;
    const std::array<const char*, 5> continuous = {plugin::ids::bowForce, plugin::ids::bowSpeed,
                                                   plugin::ids::attackAcceleration, plugin::ids::beta,
                                                   plugin::ids::outputLevel};
    const std::array<const char*, 5> patch = {plugin::ids::friction, plugin::ids::instrument,
                                              plugin::ids::body, plugin::ids::ambientTemperature,
                                              plugin::ids::string};
    float peak = 0.0f;
    int rebuilds = 0;
    bool finite = true;
    for (int b = 0; b < blocks; ++b)
    {
        // Host automation: continuous parameters every block, the instrument-defining ones every ~0.5 s.
        for (const char* id : continuous)
            p.parameters().getParameter(id)->setValueNotifyingHost(unit(rng));
        if (b % 94 == 0 && b < blocks - 200)
        {
            for (const char* id : patch)
                p.parameters().getParameter(id)->setValueNotifyingHost(unit(rng));
            ++rebuilds;
        }
        p.serviceEngineBuilds();
        midi.clear();
        std::uniform_int_distribution<int> count(0, 3), offset(0, kBlock - 1);
        if (b < blocks - 200) // the last ~1 s: everything off, the strings ring down
            for (int n = count(rng); n > 0; --n)
                midi.addEvent(randomMessage(rng), offset(rng));
        else if (b == blocks - 200)
            midi.addEvent(juce::MidiMessage::allNotesOff(1), 0);
        p.processBlock(buffer, midi);
        for (int c = 0; c < 2; ++c)
            for (int i = 0; i < kBlock; ++i)
            {
                const float y = buffer.getSample(c, i);
                finite = finite && std::isfinite(y);
                peak = std::max(peak, std::abs(y));
            }
    }
    EXPECT_TRUE(finite);
    EXPECT_LE(peak, 1.0f);
    EXPECT_EQ(p.nonFiniteSamples(), 0);
    std::cout << "[ figures  ] fuzz: " << blocks << " blocks, " << rebuilds << " instrument rebuilds, peak "
              << peak << ", runaway resets " << p.runawayResets() << "\n";
    p.releaseResources();
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
