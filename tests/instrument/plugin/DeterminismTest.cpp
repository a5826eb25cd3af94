// The demo phrase renders bit-identically across runs and block sizes; a saved and restored state renders
// exactly what the original renders.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "core/config/PresetLoader.h"
#include "instrument/plugin/PluginTestSupport.h"

namespace rosin::test
{
namespace ROSIN_FILE_LOCAL
{

TEST(PluginDeterminism, DemoPhraseIsBitIdenticalAcrossRunsAndBlockSizes)
{
    const auto reference = renderDemo("", 48000.0, 512);
    ASSERT_GT(reference.audio.size(), 48000u * 8);
    ASSERT_GT(reference.peak, 0.01f);
    EXPECT_EQ(renderDemo("", 48000.0, 512).audio, reference.audio) << "second run";
    for (int block : {1, 7, 64, 4096})
    {
        const auto r = renderDemo("", 48000.0, block);
        ASSERT_EQ(r.audio.size(), reference.audio.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < r.audio.size(); ++i)
            differing += r.audio[i] != reference.audio[i];
        EXPECT_EQ(differing, 0u) << "block size " << block;
    }
    std::cout << "[ figures  ] demo phrase: " << reference.audio.size() << " samples, peak " << reference.peak
              << ", identical for block sizes 1, 7, 64, 512 (x2), 4096\n";
}

// A DAW's export runs the plugin offline, faster than the message thread's timer: the block after a change of
// instrument must already play the new one, or an export would depend on when the timer fired. Live, the
// change waits for the builder (the timer), which this test never runs.
TEST(PluginDeterminism, OfflineTheBlockAfterAChangePlaysTheNewInstrument)
{
    plugin::RosinProcessor p;
    p.setPlayConfigDetails(0, 2, 48000.0, 256);
    p.prepareToPlay(48000.0, 256);
    juce::AudioBuffer<float> buffer(2, 256);
    juce::MidiBuffer midi;
    const auto lowest = [&p] { return p.telemetry().strings[0].read().openFrequency; };
    p.processBlock(buffer, midi);
    EXPECT_NEAR(lowest(), 65.41f, 0.05f); // the cello's C string

    p.setParameterValue(engine::ids::instrument, 1.0f); // violin
    p.processBlock(buffer, midi);
    EXPECT_NEAR(lowest(), 65.41f, 0.05f) << "live: the builder has not run yet";
    p.setNonRealtime(true);
    p.processBlock(buffer, midi);
    EXPECT_NEAR(lowest(), 196.0f, 0.1f) << "offline: the violin's G string at the next block";
    p.setNonRealtime(false);
    p.releaseResources();
}

TEST(PluginState, SaveAndRestoreGivesAnIdenticalNextRender)
{
    plugin::RosinProcessor original;
    original.setProgramByName("cello-classical");
    setParameter(original, plugin::ids::bowForce, 1.7f);
    setParameter(original, plugin::ids::beta, 0.12f);
    setParameter(original, plugin::ids::outputLevel, -6.0f);
    setParameter(original, plugin::ids::ambientTemperature, 26.0f);
    juce::MemoryBlock saved;
    original.getStateInformation(saved);

    plugin::RosinProcessor restored;
    restored.setStateInformation(saved.getData(), static_cast<int>(saved.getSize()));
    EXPECT_EQ(restored.getProgramName(restored.getCurrentProgram()), "cello-classical");
    for (const char* id : engine::allParameterIds())
        EXPECT_EQ(restored.parameters().getParameter(id)->getValue(),
                  original.parameters().getParameter(id)->getValue())
            << id;

    engine::MidiRenderSettings settings;
    settings.tailSeconds = 0.5;
    const auto a = test::renderMidi(original, demoPhrase(), settings);
    const auto b = test::renderMidi(restored, demoPhrase(), settings);
    EXPECT_EQ(a.audio, b.audio);
    // And the restored state is not simply the default one.
    EXPECT_NE(renderDemo("", 48000.0, 512, 0.5).audio, a.audio);
}

// A project saved before the musical mapping existed has no "mapping" in its state: it keeps playing with
// the lab mapping it was made with, although a new instance starts with the musical default program.
TEST(PluginState, AStateSavedWithoutAMappingKeepsTheLabMapping)
{
    plugin::RosinProcessor before;
    before.setProgramByName("cello-plastic");
    juce::MemoryBlock saved;
    before.getStateInformation(saved);
    auto xml = juce::AudioProcessor::getXmlFromBinary(saved.getData(), static_cast<int>(saved.getSize()));
    ASSERT_NE(xml, nullptr);
    for (auto* child = xml->getFirstChildElement(); child != nullptr;)
    {
        auto* next = child->getNextElement();
        if (child->getStringAttribute("id") == plugin::ids::mapping)
            xml->removeChildElement(child, true);
        child = next;
    }
    xml->setAttribute("stateVersion", 1);
    juce::MemoryBlock old;
    juce::AudioProcessor::copyXmlToBinary(*xml, old);

    plugin::RosinProcessor restored;
    ASSERT_EQ(restored.parameters().getParameter(plugin::ids::mapping)->getCurrentValueAsText(), "musical");
    restored.setStateInformation(old.getData(), static_cast<int>(old.getSize()));
    EXPECT_EQ(restored.parameters().getParameter(plugin::ids::mapping)->getCurrentValueAsText(), "lab");
}

TEST(PluginState, RejectsForeignDataWithoutChangingAnything)
{
    plugin::RosinProcessor p;
    setParameter(p, plugin::ids::bowForce, 2.0f);
    const float before = p.parameters().getParameter(plugin::ids::bowForce)->getValue();
    const char junk[] = "not a state";
    p.setStateInformation(junk, sizeof(junk));
    EXPECT_EQ(p.parameters().getParameter(plugin::ids::bowForce)->getValue(), before);
}

TEST(PluginPrograms, EveryFactoryPresetIsAProgram)
{
    plugin::RosinProcessor p;
    const auto names = instrumentPresetNames();
    ASSERT_GE(names.size(), 9u); // the rig preset (cantilever) is the only one left out
    ASSERT_EQ(p.getNumPrograms(), static_cast<int>(names.size()));
    for (int i = 0; i < p.getNumPrograms(); ++i)
        EXPECT_EQ(p.getProgramName(i).toStdString(), names[static_cast<std::size_t>(i)]);
    EXPECT_EQ(p.getProgramName(p.getCurrentProgram()), engine::kDefaultProgramName);
    // The default program plays with the musical mapping, a lab program with the lab's.
    EXPECT_EQ(p.parameters().getParameter(engine::ids::mapping)->getCurrentValueAsText(), "musical");
    p.setProgramByName("cello-plastic");
    EXPECT_EQ(p.parameters().getParameter(engine::ids::mapping)->getCurrentValueAsText(), "lab");
    p.setProgramByName("schumacher-rig");
    EXPECT_EQ(p.parameters().getParameter(plugin::ids::instrument)->getCurrentValueAsText(), "violin");
    EXPECT_EQ(p.parameters().getParameter(plugin::ids::body)->getValue(), 0.0f);
}

// The programs are compiled into the plugin: a bundle installed or copied anywhere has them, whatever preset
// folder (none here) the running program would find.
TEST(PluginPrograms, TheProgramsNeedNoPresetFolder)
{
    const auto names = instrumentPresetNames(); // from the source tree's presets/
    const std::filesystem::path empty = std::filesystem::temp_directory_path() / "rosin-no-presets";
    std::filesystem::create_directories(empty);
    ::setenv("ROSIN_PRESET_DIR", empty.c_str(), 1);
    plugin::RosinProcessor p;
    ::unsetenv("ROSIN_PRESET_DIR");
    std::filesystem::remove_all(empty);
    ASSERT_EQ(p.getNumPrograms(), static_cast<int>(names.size()));
    for (int i = 0; i < p.getNumPrograms(); ++i)
        EXPECT_EQ(p.getProgramName(i).toStdString(), names[static_cast<std::size_t>(i)]);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::test
