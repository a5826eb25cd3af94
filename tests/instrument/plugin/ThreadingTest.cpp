// The host's threads at once: an audio thread runs processBlock without pause while the "message thread"
// changes the friction law, instrument, body and output, switches programs, saves and restores the state,
// presses on-screen keys and reads the editor's readouts, servicing engine builds as the processor's timer
// would. Output stays finite and audio keeps running; CI runs this test under ThreadSanitizer as well
// (Resources/docs/tests.md), which fails it on any data race between the two sides of the lock-free engine
// swap.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <thread>

#include "instrument/plugin/PluginTestSupport.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

void runAudio(plugin::RosinProcessor& p, const std::atomic<bool>& stop, std::atomic<long>& blocks,
              std::atomic<long>& nonFinite)
{
    constexpr int kBlock = 128;
    juce::AudioBuffer<float> buffer(2, kBlock);
    juce::MidiBuffer on, off, none;
    on.addEvent(juce::MidiMessage::noteOn(1, 50, 0.8f), 5);
    on.addEvent(juce::MidiMessage::noteOn(1, 57, 0.7f), 9);
    off.addEvent(juce::MidiMessage::allNotesOff(1), 0);
    for (long b = 0; !stop.load(); ++b)
    {
        juce::MidiBuffer& midi = b % 200 == 0 ? on : (b % 200 == 150 ? off : none);
        p.processBlock(buffer, midi);
        for (int c = 0; c < buffer.getNumChannels(); ++c)
            for (int n = 0; n < kBlock; ++n)
                if (!std::isfinite(buffer.getSample(c, n)))
                    ++nonFinite;
        blocks.fetch_add(1);
    }
}

void hostRound(plugin::RosinProcessor& p, int round)
{
    setParameter(p, plugin::ids::friction, static_cast<float>(round % 6));
    setParameter(p, plugin::ids::bowForce, 0.5f + 0.1f * static_cast<float>(round % 10));
    if (round % 4 == 0)
        setParameter(p, plugin::ids::instrument, static_cast<float>((round / 4) % 2));
    if (round % 3 == 0)
        setParameter(p, plugin::ids::body, static_cast<float>(round % 2));
    setParameter(p, plugin::ids::output, static_cast<float>(round % 3));
    if (round % 5 == 0)
    {
        juce::MemoryBlock state;
        p.getStateInformation(state);
        p.setStateInformation(state.getData(), static_cast<int>(state.getSize()));
    }
    if (round % 7 == 0)
        p.setCurrentProgram(round % p.getNumPrograms());
    if (round % 2 == 0)
        p.keyboardState().noteOn(1, 62 + round % 5, 0.6f);
    else
        p.keyboardState().allNotesOff(1);
    double sum = 0.0;
    for (int s = 0; s < p.telemetry().stringCount.load(); ++s)
        sum += p.telemetry().strings[static_cast<std::size_t>(s)].read().bowForce;
    EXPECT_TRUE(std::isfinite(sum));
    p.serviceEngineBuilds();
}

TEST(PluginThreads, EngineSwapsStateAndReadoutsWhileAudioRuns)
{
    plugin::RosinProcessor p;
    p.setPlayConfigDetails(0, 2, 48000.0, 128);
    p.prepareToPlay(48000.0, 128);
    std::atomic<bool> stop{false};
    std::atomic<long> blocks{0}, nonFinite{0};
    std::thread audio(runAudio, std::ref(p), std::cref(stop), std::ref(blocks), std::ref(nonFinite));
    constexpr int kRounds = 60;
    for (int round = 0; round < kRounds; ++round)
    {
        const long before = blocks.load();
        hostRound(p, round);
        // Let the audio thread take the new engine before the next change (as real time would).
        while (blocks.load() < before + 4)
            std::this_thread::yield();
    }
    stop = true;
    audio.join();
    p.serviceEngineBuilds();
    EXPECT_EQ(nonFinite.load(), 0);
    EXPECT_EQ(p.nonFiniteSamples(), 0);
    EXPECT_GE(blocks.load(), 4L * kRounds);
    std::printf("[figure] %d host rounds, %ld audio blocks alongside\n", kRounds, blocks.load());
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
