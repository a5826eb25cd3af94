// The built VST3 and LV2 bundles, loaded through JUCE's hosting classes (VST3PluginFormat, LV2PluginFormat)
// and checked headless as a validator would: an instrument taking MIDI; a note renders finite, bounded,
// audible output at several sample rates and block sizes; every parameter survives fuzzing; state restores
// into a new instance with the same parameters and the same output; programs; prepare/release cycles;
// instance lifetime. No editor is opened. The plugin is reached only through the bundles (this executable
// does not link it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "pluginhost/HostHarness.h"
#include "pluginhost/XlibHostSetup.h"

using namespace rosin::pluginhost;

namespace ROSIN_FILE_LOCAL
{

class PluginHost : public ::testing::TestWithParam<const char*>
{
  protected:
    juce::String formatName() const { return GetParam(); }
};

// --- the checks
// ---------------------------------------------------------------------------------------------

TEST_P(PluginHost, ScansAsAMidiInstrumentWithAnOutput)
{
    const auto& desc = description(formatName());
    ASSERT_FALSE(desc.fileOrIdentifier.isEmpty());
    EXPECT_EQ(desc.pluginFormatName, formatName());
    EXPECT_EQ(desc.name, "Rosin");
    EXPECT_TRUE(desc.isInstrument) << formatName() << " description is not an instrument";
    EXPECT_EQ(desc.numInputChannels, 0);
    EXPECT_GE(desc.numOutputChannels, 1);

    auto plugin = createInstance(formatName());
    ASSERT_NE(plugin, nullptr);
    EXPECT_TRUE(plugin->acceptsMidi());
    EXPECT_FALSE(plugin->producesMidi());
    EXPECT_GE(plugin->getTotalNumOutputChannels(), 1);
    EXPECT_EQ(plugin->getTotalNumInputChannels(), 0);
    EXPECT_GE(plugin->getTailLengthSeconds(), 0.0);
    std::cout << "[          ] " << formatName() << ": " << desc.name << " by " << desc.manufacturerName
              << ", " << desc.fileOrIdentifier << ", " << plugin->getTotalNumOutputChannels() << " outputs, "
              << plugin->getParameters().size() << " parameters, " << plugin->getNumPrograms()
              << " programs, editor " << (plugin->hasEditor() ? "yes" : "no") << " (not opened), latency "
              << plugin->getLatencySamples() << "\n";
}

TEST_P(PluginHost, NoteRendersAtEverySampleRateAndBlockSize)
{
    auto plugin = createInstance(formatName());
    ASSERT_NE(plugin, nullptr);
    const std::vector<std::pair<const char*, std::vector<int>>> blockings = {
        {"1", {1}},
        {"64", {64}},
        {"128", {128}},
        {"256", {256}},
        {"512", {512}},
        {"1024", {1024}},
        {"variable", {1, 17, 512, 3, 64, 250, 2, 511, 128}}}; // pluginval's 5 sizes, and more
    for (double sampleRate : {44100.0, 48000.0, 96000.0})
        for (const auto& [label, sizes] : blockings)
        {
            SCOPED_TRACE(formatName() + " at " + juce::String(sampleRate) + " Hz, blocks " + label);
            const int maxBlock = *std::max_element(sizes.begin(), sizes.end());
            plugin->releaseResources();
            plugin->setRateAndBufferSizeDetails(sampleRate, maxBlock);
            prepare(*plugin, sampleRate, maxBlock);
            const auto r = render(*plugin, notePlan(sampleRate, sizes));
            EXPECT_EQ(r.nonFinite, 0);
            EXPECT_LE(r.peak, kOutputBound);
            EXPECT_GT(r.rmsDuringNote, kSilenceRms) << "silent during the note";
        }
    plugin->releaseResources();
}

TEST_P(PluginHost, EveryParameterSurvivesFuzzing)
{
    auto plugin = createInstance(formatName());
    ASSERT_NE(plugin, nullptr);
    auto params = plugin->getParameters();
    ASSERT_GT(params.size(), 0);
    for (auto* p : params)
    {
        SCOPED_TRACE(formatName() + " parameter " + juce::String(p->getParameterIndex()));
        EXPECT_FALSE(p->getName(64).isEmpty());
        const float v = p->getValue();
        EXPECT_GE(v, 0.0f);
        EXPECT_LE(v, 1.0f);
        EXPECT_GE(p->getDefaultValue(), 0.0f);
        EXPECT_LE(p->getDefaultValue(), 1.0f);
        for (float x : {0.0f, 0.5f, 1.0f})
            (void)p->getText(x, 32); // must not crash
    }

    constexpr double sampleRate = 48000.0;
    constexpr int blockSize = 256;
    plugin->setRateAndBufferSizeDetails(sampleRate, blockSize);
    prepare(*plugin, sampleRate, blockSize);
    std::mt19937 rng(20261122u);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    RenderPlan plan;
    plan.blockSizes = {blockSize};
    plan.totalSamples = 300 * blockSize;
    plan.noteOnAt = 0;
    plan.beforeBlock = [&](int block)
    {
        // A handful of parameters per block, extremes a third of the time; now and then all of them.
        const int count = block % 50 == 0 ? params.size() : 3;
        for (int k = 0; k < count; ++k)
        {
            auto* p =
                params[block % 50 == 0 ? k : static_cast<int>(rng() % static_cast<unsigned>(params.size()))];
            const unsigned pick = rng() % 6;
            const float value = pick == 0 ? 0.0f : pick == 1 ? 1.0f : uniform(rng);
            p->setValue(value);
        }
        if (block % 10 == 0)
            pumpMessages(1); // lets the plugin rebuild its instrument while audio runs, as in a host
    };
    const auto r = render(*plugin, plan);
    EXPECT_EQ(r.nonFinite, 0) << formatName() << ": non-finite samples while fuzzing";
    EXPECT_LE(r.peak, kOutputBound);
    for (auto* p : params)
    {
        EXPECT_GE(p->getValue(), 0.0f);
        EXPECT_LE(p->getValue(), 1.0f);
    }
    plugin->releaseResources();
    destroy(plugin); // a rebuild may be running (see settleLv2)
}

/// A saved and a restored value agree: exactly for continuous parameters, by their text for stepped ones (a
/// host caches the value it set, the plugin rounds it to the step).
void expectSameValue(juce::AudioProcessorParameter& saved, juce::AudioProcessorParameter& restored,
                     const juce::String& what)
{
    const float a = saved.getValue(), b = restored.getValue();
    if (restored.isDiscrete() || restored.isBoolean())
        EXPECT_EQ(restored.getText(b, 64), saved.getText(a, 64)) << what << " " << saved.getName(64);
    else
        EXPECT_NEAR(b, a, 1.0e-6f) << what << " " << saved.getName(64) << ": restored as "
                                   << restored.getText(b, 32) << ", saved as " << saved.getText(a, 32);
}

struct StateRoundTrip
{
    std::unique_ptr<juce::AudioPluginInstance> original, restored;
    Render originalRender, restoredRender;
};

/// Random values for the plugin's parameters, a few blocks so they reach its processor, state saved, a new
/// instance given that state; then the same MIDI through both, each freshly prepared (prepareToPlay rebuilds
/// the instrument).
StateRoundTrip roundTripState(const juce::String& formatName)
{
    constexpr double sampleRate = 48000.0;
    constexpr int blockSize = 128;
    StateRoundTrip t;
    t.original = createInstance(formatName, sampleRate, blockSize);
    if (t.original == nullptr)
        return t;
    t.original->setRateAndBufferSizeDetails(sampleRate, blockSize);
    prepare(*t.original, sampleRate, blockSize);
    std::mt19937 rng(7u);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    auto params = t.original->getParameters();
    for (int i : pluginParameters(*t.original))
        params[i]->setValue(uniform(rng));
    RenderPlan settle;
    settle.totalSamples = 8 * blockSize;
    settle.blockSizes = {blockSize};
    settle.noteOnAt = -1;
    render(*t.original, settle);
    pumpMessages(50);
    render(*t.original, settle);

    juce::MemoryBlock state;
    t.original->getStateInformation(state);
    EXPECT_GT(state.getSize(), 0u);
    t.restored = createInstance(formatName, sampleRate, blockSize);
    if (t.restored == nullptr)
        return t;
    t.restored->setStateInformation(state.getData(), static_cast<int>(state.getSize()));
    pumpMessages(50);

    t.original->releaseResources();
    prepare(*t.original, sampleRate, blockSize);
    t.restored->setRateAndBufferSizeDetails(sampleRate, blockSize);
    prepare(*t.restored, sampleRate, blockSize);
    const auto plan = notePlan(sampleRate, {blockSize});
    t.originalRender = render(*t.original, plan);
    t.restoredRender = render(*t.restored, plan);
    pumpMessages(50);
    return t;
}

/// The two renders of a state round trip are the same, sample for sample.
void expectSameRender(const StateRoundTrip& t, const juce::String& what)
{
    const auto& a = t.originalRender;
    const auto& b = t.restoredRender;
    ASSERT_EQ(a.samples.size(), b.samples.size());
    std::size_t differing = 0, first = a.samples.size();
    float maxDifference = 0.0f;
    for (std::size_t i = 0; i < a.samples.size(); ++i)
        if (a.samples[i] != b.samples[i])
        {
            ++differing;
            first = std::min(first, i);
            maxDifference = std::max(maxDifference, std::abs(a.samples[i] - b.samples[i]));
        }
    EXPECT_EQ(differing, 0u) << what << ": restored instance renders differently: " << differing << " of "
                             << a.samples.size() << " samples differ, first at " << first
                             << ", max difference " << maxDifference << " (rms " << a.rmsDuringNote << " vs "
                             << b.rmsDuringNote << ")";
}

TEST_P(PluginHost, StateRestoresIntoANewInstance)
{
    auto t = roundTripState(formatName());
    ASSERT_NE(t.original, nullptr);
    ASSERT_NE(t.restored, nullptr);
    EXPECT_EQ(t.originalRender.nonFinite + t.restoredRender.nonFinite, 0);
    EXPECT_GT(t.originalRender.rmsDuringNote, kSilenceRms);
    EXPECT_GT(t.restoredRender.rmsDuringNote, kSilenceRms);
    // The same output. (LV2: only because prepare() lets the re-instantiated plugin finish the rebuild its
    // restored state starts; without that wait the restored instance switched instrument a few blocks into
    // the note in two runs of three, see settleLv2.)
    expectSameRender(t, formatName());

    // The parameter values the host sees (LV2: only once the restored instance has run; checked after it
    // has).
    auto saved = t.original->getParameters();
    auto restored = t.restored->getParameters();
    ASSERT_EQ(saved.size(), restored.size());
    for (int i : pluginParameters(*t.original))
        expectSameValue(*saved[i], *restored[i], formatName() + " parameter " + juce::String(i));
    t.original->releaseResources();
    t.restored->releaseResources();
}

TEST_P(PluginHost, ProgramsHaveNamesAndPlay)
{
    auto plugin = createInstance(formatName());
    ASSERT_NE(plugin, nullptr);
    const int count = plugin->getNumPrograms();
    std::cout << "[          ] " << formatName() << ": " << count << " programs:";
    for (int i = 0; i < count; ++i)
        std::cout << (i ? ", " : " ") << plugin->getProgramName(i);
    std::cout << "\n";
    ASSERT_GE(count, 1);

    constexpr double sampleRate = 48000.0;
    constexpr int blockSize = 512;
    for (int i = 0; i < count; ++i)
    {
        SCOPED_TRACE(formatName() + " program " + juce::String(i) + " " + plugin->getProgramName(i));
        EXPECT_FALSE(plugin->getProgramName(i).isEmpty());
        plugin->setCurrentProgram(i);
        pumpMessages(20);
        EXPECT_EQ(plugin->getCurrentProgram(), i);
        prepare(*plugin, sampleRate, blockSize); // builds the program's instrument
        const auto r = render(*plugin, notePlan(sampleRate, {blockSize}, 0.3, 0.25));
        EXPECT_EQ(r.nonFinite, 0);
        EXPECT_LE(r.peak, kOutputBound);
        EXPECT_GT(r.rmsDuringNote, kSilenceRms) << "silent during the note";
        plugin->releaseResources();
    }
    destroy(plugin);
}

void prepareReleaseCycles(juce::AudioPluginInstance& plugin, const juce::String& what,
                          std::vector<double> rates, bool rebuildEachCycle)
{
    const int blocks[] = {512, 32, 1024, 1, 256};
    for (int cycle = 0; cycle < 10; ++cycle)
    {
        const double sampleRate = rates[static_cast<std::size_t>(cycle) % rates.size()];
        const int blockSize = blocks[(cycle * 3) % 5];
        SCOPED_TRACE(what + " cycle " + juce::String(cycle) + " at " + juce::String(sampleRate) + " Hz, " +
                     juce::String(blockSize));
        plugin.setRateAndBufferSizeDetails(sampleRate, blockSize);
        prepare(plugin, sampleRate, blockSize);
        if (cycle % 3 == 1)
            prepare(plugin, sampleRate, blockSize); // twice without a release, as some hosts do
        if (cycle % 4 == 2)
            plugin.reset();
        // A new instrument each cycle, so the plugin is rebuilding it when the next prepare comes.
        if (rebuildEachCycle)
            for (auto* p : plugin.getParameters())
                if (p->getName(64) == "Instrument")
                    p->setValue(cycle % 2 == 0 ? 1.0f : 0.0f);
        const auto r = render(plugin, notePlan(sampleRate, {blockSize}, 0.08, 0.06));
        EXPECT_EQ(r.nonFinite, 0);
        EXPECT_LE(r.peak, kOutputBound);
        pumpMessages(1);
        plugin.releaseResources();
        if (cycle % 2 == 0)
            plugin.releaseResources(); // twice
    }
}

TEST_P(PluginHost, SurvivesRepeatedPrepareAndRelease)
{
    auto plugin = createInstance(formatName());
    ASSERT_NE(plugin, nullptr);
    // LV2 with an instrument rebuild in flight at the next prepare is
    // PluginHostLv2.SurvivesPrepareWhileRebuilding.
    const bool rebuild = formatName() != "LV2";
    prepareReleaseCycles(*plugin, formatName(), {48000.0}, rebuild);
    prepareReleaseCycles(*plugin, formatName(), {44100.0, 96000.0, 48000.0, 22050.0, 192000.0}, rebuild);
}

// pluginval's "non-releasing audio processing": prepared again with other settings while prepared, never
// released in between; every preparation plays.
TEST_P(PluginHost, PlaysWhenPreparedAgainWithoutARelease)
{
    auto plugin = createInstance(formatName());
    ASSERT_NE(plugin, nullptr);
    for (const auto& [sampleRate, blockSize] :
         std::vector<std::pair<double, int>>{{44100.0, 64}, {48000.0, 512}, {96000.0, 1024}, {48000.0, 128}})
    {
        SCOPED_TRACE(formatName() + " at " + juce::String(sampleRate) + " Hz, blocks " +
                     juce::String(blockSize));
        prepare(*plugin, sampleRate, blockSize);
        const auto r = render(*plugin, notePlan(sampleRate, {blockSize}, 0.3, 0.25));
        EXPECT_EQ(r.nonFinite, 0);
        EXPECT_LE(r.peak, kOutputBound);
        EXPECT_GT(r.rmsDuringNote, kSilenceRms) << "silent during the note";
    }
    plugin->releaseResources();
    destroy(plugin);
}

// Regression test for a crash this host found: JUCE 7.0.5's LV2 host re-instantiates the plugin on every
// prepareToPlay (LV2 fixes the sample rate at instantiation) and destroys the old instance on the host's
// thread, while the old RosinProcessor's juce::Timer may be building an engine on the plugin's own "JUCE
// Plugin Message Thread". ~RosinProcessor now waits for a running build; before, the build finished on the
// destroyed processor (SIGBUS/SIGSEGV in EngineSlot::publish()). No settling delay here, on purpose.
TEST(PluginHostLv2, SurvivesPrepareWhileRebuilding)
{
    settleLv2 = false;
    auto plugin = createInstance("LV2");
    ASSERT_NE(plugin, nullptr);
    prepareReleaseCycles(*plugin, "LV2", {44100.0, 96000.0, 48000.0, 22050.0, 192000.0}, true);
    plugin.reset();
    settleLv2 = true;
}

TEST_P(PluginHost, InstancesCanBeDeletedAndRecreated)
{
    for (int i = 0; i < 4; ++i)
    {
        auto plugin = createInstance(formatName());
        ASSERT_NE(plugin, nullptr);
        if (i % 2 == 1)
        {
            prepare(*plugin, 48000.0, 256);
            render(*plugin, notePlan(48000.0, {256}, 0.05, 0.04));
        }
        // Deleted while prepared (odd i) and while never prepared (even i).
    }
    // Several alive at once, deleted in another order than made.
    std::vector<std::unique_ptr<juce::AudioPluginInstance>> alive;
    for (int i = 0; i < 3; ++i)
    {
        alive.push_back(createInstance(formatName()));
        ASSERT_NE(alive.back(), nullptr);
        prepare(*alive.back(), 48000.0, 256);
    }
    std::vector<Render> renders;
    for (auto& plugin : alive)
        renders.push_back(render(*plugin, notePlan(48000.0, {256}, 0.1, 0.08)));
    for (const auto& r : renders)
    {
        EXPECT_EQ(r.nonFinite, 0);
        EXPECT_GT(r.rmsDuringNote, kSilenceRms);
        // Instances share nothing audible: each renders what the others do.
        EXPECT_EQ(r.samples, renders.front().samples) << formatName() << ": instances render differently";
    }
    alive.erase(alive.begin() + 1);
    alive.front()->releaseResources();
    alive.erase(alive.begin());
    alive.clear();
    pumpMessages(20);
}

INSTANTIATE_TEST_SUITE_P(Formats, PluginHost, ::testing::Values("VST3", "LV2"),
                         [](const auto& info) { return std::string(info.param); });

} // namespace ROSIN_FILE_LOCAL

int main(int argc, char** argv)
{
    prepareXlibAsADesktopHostDoes();
    juce::ScopedJuceInitialiser_GUI juce;
    ::testing::InitGoogleTest(&argc, argv);
    const int result = RUN_ALL_TESTS();
    releaseFormats(); // before the message manager goes
    return result;
}
