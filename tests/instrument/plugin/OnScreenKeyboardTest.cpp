// Playable without a MIDI controller: the editor's on-screen keyboard plays the strings
// through a lock-free queue, without allocating on the audio thread; and before any audio runs the lanes and
// the Schelleng diagram already know the instrument's strings.
#include <gtest/gtest.h>

#include <cmath>

#include "instrument/plugin/PluginTestSupport.h"
#include "instrument/plugin/ThreadAllocationCounter.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

constexpr int kBlock = 256;
constexpr double kFs = 48000.0;

double blockRms(const juce::AudioBuffer<float>& b)
{
    return b.getRMSLevel(0, 0, b.getNumSamples());
}

// A key pressed on the keyboard bows a string; releasing it lifts the bow. No heap allocation in any of the
// processBlock calls, the ones that take the keyboard's notes included.
TEST(OnScreenKeyboard, KeysPlayAndReleaseWithoutAllocating)
{
    plugin::RosinProcessor p;
    p.setPlayConfigDetails(0, 2, kFs, kBlock);
    p.prepareToPlay(kFs, kBlock);
    juce::AudioBuffer<float> buffer(2, kBlock);
    juce::MidiBuffer none;
    long allocations = 0;
    const auto run = [&](int blocks)
    {
        double rms = 0.0;
        for (int b = 0; b < blocks; ++b)
        {
            ThreadAllocationCounter counter;
            p.processBlock(buffer, none);
            allocations += counter.count();
            rms = blockRms(buffer);
        }
        return rms; // of the last block
    };
    EXPECT_EQ(run(10), 0.0); // silence before a key
    p.keyboardState().noteOn(1, 50, 0.7f);
    const double playing = run(static_cast<int>(0.8 * kFs / kBlock));
    EXPECT_GT(playing, 1e-3);
    EXPECT_EQ(p.telemetry().strings[2].read().bowing, true); // D3 sounds on the cello's third string
    p.keyboardState().noteOff(1, 50, 0.0f);
    const double released = run(static_cast<int>(1.5 * kFs / kBlock));
    EXPECT_LT(released, 0.3 * playing); // the bow lifted and the string rings down
    EXPECT_FALSE(p.telemetry().strings[2].read().bowing);
    EXPECT_EQ(allocations, 0);
}

// Before prepareToPlay the editor's lanes show the program's four strings at rest (not "no string"), with
// what the diagram needs: open frequency, Z0, the friction law's mu_s at the bow force parameter.
TEST(OnScreenKeyboard, LanesKnowTheStringsBeforeAudioStarts)
{
    plugin::RosinProcessor p;
    ASSERT_EQ(p.telemetry().stringCount.load(), 4);
    const double cello[] = {65.41, 98.0, 146.83, 220.0};
    for (int s = 0; s < 4; ++s)
    {
        const plugin::StringReadout r = p.telemetry().strings[static_cast<std::size_t>(s)].read();
        EXPECT_NEAR(r.openFrequency, cello[s], 0.01 * cello[s]) << s;
        EXPECT_GT(r.impedance, 0.0f);
        EXPECT_GT(r.muStatic, 0.0f);
        EXPECT_FALSE(r.bowing);
    }
    ASSERT_TRUE(p.setProgramByName("violin-thermal"));
    EXPECT_NEAR(p.telemetry().strings[0].read().openFrequency, 196.0, 2.0); // G3, before any audio
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
