// pluginval's "editor" and "open editor whilst processing", through the bundles: an audio thread renders
// blocks without pause while the host's message thread opens the plugin's editor in a desktop window, lets it
// draw, closes it and opens it again, three times. Needs a display: CTest runs it under xvfb-run
// (pluginhost.editor); the main executable's Xlib is set up as a desktop host's (XlibHostSetup.h).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <thread>

#include "pluginhost/HostHarness.h"

using namespace rosin::pluginhost;

namespace ROSIN_FILE_LOCAL
{

class PluginHostEditor : public ::testing::TestWithParam<const char*>
{
};

TEST_P(PluginHostEditor, OpensAndClosesWhileAudioRuns)
{
    if (std::getenv("DISPLAY") == nullptr)
        GTEST_SKIP() << "no display (CTest runs this test under xvfb-run)";
    constexpr double sampleRate = 48000.0;
    constexpr int blockSize = 256;
    auto plugin = createInstance(GetParam(), sampleRate, blockSize);
    ASSERT_NE(plugin, nullptr);
    prepare(*plugin, sampleRate, blockSize);
    ASSERT_TRUE(plugin->hasEditor());
    std::atomic<bool> stop{false};
    std::atomic<long> blocks{0}, nonFinite{0};
    std::atomic<float> peak{0.0f};
    std::thread audio(
        [&]
        {
            juce::AudioBuffer<float> buffer(plugin->getTotalNumOutputChannels(), blockSize);
            juce::MidiBuffer midi;
            for (long b = 0; !stop.load(); ++b)
            {
                midi.clear();
                if (b % 100 == 0)
                    midi.addEvent(juce::MidiMessage::noteOn(1, kNote, static_cast<juce::uint8>(90)), 0);
                if (b % 100 == 80)
                    midi.addEvent(juce::MidiMessage::noteOff(1, kNote), 0);
                buffer.clear();
                plugin->processBlock(buffer, midi);
                for (int c = 0; c < buffer.getNumChannels(); ++c)
                    for (int n = 0; n < blockSize; ++n)
                    {
                        const float x = buffer.getSample(c, n);
                        nonFinite += std::isfinite(x) ? 0 : 1;
                        if (std::isfinite(x) && std::abs(x) > peak.load())
                            peak.store(std::abs(x));
                    }
                blocks.fetch_add(1);
            }
        });
    for (int round = 0; round < 3; ++round)
    {
        std::unique_ptr<juce::AudioProcessorEditor> editor(plugin->createEditorIfNeeded());
        ASSERT_NE(editor, nullptr) << GetParam() << ": no editor";
        EXPECT_GT(editor->getWidth(), 0);
        EXPECT_GT(editor->getHeight(), 0);
        juce::DocumentWindow window("Rosin", juce::Colours::black, juce::DocumentWindow::closeButton);
        window.setContentNonOwned(editor.get(), true);
        window.setVisible(true);
        const long before = blocks.load();
        pumpMessages(400); // the editor's timers read the readouts while audio runs
        EXPECT_TRUE(editor->isShowing()) << GetParam() << ", round " << round;
        EXPECT_GT(blocks.load() - before, 10L) << "the audio thread stalled while the editor was open";
        window.clearContentComponent();
        editor.reset();
        pumpMessages(50);
    }
    stop = true;
    audio.join();
    EXPECT_EQ(nonFinite.load(), 0);
    EXPECT_GT(peak.load(), kSilenceRms) << "silent while the editor was open";
    plugin->releaseResources();
    destroy(plugin);
}

INSTANTIATE_TEST_SUITE_P(Formats, PluginHostEditor, ::testing::Values("VST3", "LV2"),
                         [](const auto& info) { return std::string(info.param); });

} // namespace ROSIN_FILE_LOCAL
