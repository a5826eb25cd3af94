// processBlock allocates nothing after prepareToPlay: notes, controllers, pressure, bend, a parameter change
// and an engine swap (friction law rebuilt off the "audio" thread) included.
#include <gtest/gtest.h>

#include <iostream>

#include "instrument/plugin/PluginTestSupport.h"
#include "instrument/plugin/ThreadAllocationCounter.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

TEST(PluginRealTime, ProcessBlockDoesNotAllocateAfterPrepareToPlay)
{
    constexpr int kBlock = 256;
    plugin::RosinProcessor p;
    p.setPlayConfigDetails(0, 2, 48000.0, kBlock);
    p.prepareToPlay(48000.0, kBlock);
    juce::AudioBuffer<float> buffer(2, kBlock);

    // Every block's MIDI, built (allocating) before counting.
    std::vector<juce::MidiBuffer> blocks(64);
    blocks[0].addEvent(juce::MidiMessage::noteOn(1, 50, 0.8f), 3);
    blocks[0].addEvent(juce::MidiMessage::noteOn(1, 57, 0.8f), 3);
    blocks[4].addEvent(juce::MidiMessage::controllerEvent(1, 1, 100), 17);
    blocks[5].addEvent(juce::MidiMessage::controllerEvent(1, 11, 20), 200);
    blocks[6].addEvent(juce::MidiMessage::pitchWheel(1, 12000), 5);
    blocks[7].addEvent(juce::MidiMessage::channelPressureChange(1, 90), 0);
    blocks[8].addEvent(juce::MidiMessage::aftertouchChange(1, 57, 30), 100);
    blocks[9].addEvent(juce::MidiMessage::controllerEvent(1, 64, 127), 1);
    blocks[10].addEvent(juce::MidiMessage::noteOff(1, 50), 9);
    blocks[12].addEvent(juce::MidiMessage::noteOn(1, 57, 1.0f), 9);
    blocks[20].addEvent(juce::MidiMessage::controllerEvent(1, 64, 0), 0);
    blocks[30].addEvent(juce::MidiMessage::noteOn(1, 36, 0.5f), 255);
    blocks[40].addEvent(juce::MidiMessage::allNotesOff(1), 40);

    long allocations = 0;
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        if (b == 24)
        {
            // Off the audio thread: a parameter change and the rebuild it asks for (allocations allowed).
            setParameter(p, plugin::ids::friction, static_cast<float>(physics::FrictionModel::Classical));
            setParameter(p, plugin::ids::bowForce, 2.0f);
            p.serviceEngineBuilds();
        }
        const plugin::Engine* before = p.activeEngine();
        {
            ThreadAllocationCounter counter;
            p.processBlock(buffer, blocks[b]);
            allocations += counter.count();
        }
        if (b == 24)
            EXPECT_NE(p.activeEngine(), before) << "the rebuilt engine was not swapped in";
    }
    EXPECT_EQ(allocations, 0);
    EXPECT_EQ(p.nonFiniteSamples(), 0);
    std::cout << "[ figures  ] heap allocations in " << blocks.size()
              << " processBlock calls: " << allocations << "\n";
    p.serviceEngineBuilds(); // frees the retired engine
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
