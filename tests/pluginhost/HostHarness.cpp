// The host harness of the plugin-hosting tests: finding and loading the built bundles, preparing,
// rendering with MIDI, and letting LV2 instances settle. See HostHarness.h.
#include "pluginhost/HostHarness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

namespace rosin::pluginhost
{

// D4: on every string instrument's range (violin, viola, cello)

// --- the host
// -----------------------------------------------------------------------------------------------

namespace
{
std::unique_ptr<juce::AudioPluginFormatManager> formatManager; // made and freed under main's message manager
} // namespace

juce::AudioPluginFormatManager& formats()
{
    if (formatManager == nullptr)
        formatManager = std::make_unique<juce::AudioPluginFormatManager>();
    return *formatManager;
}

juce::AudioPluginFormat* format(const juce::String& name)
{
    auto& manager = formats();
    if (manager.getNumFormats() == 0)
    {
        manager.addFormat(new juce::VST3PluginFormat());
        manager.addFormat(new juce::LV2PluginFormat());
    }
    for (int i = 0; i < manager.getNumFormats(); ++i)
        if (manager.getFormat(i)->getName() == name)
            return manager.getFormat(i);
    return nullptr;
}

/// ROSIN_PLUGINHOST_VST3 / ROSIN_PLUGINHOST_LV2 point the test at other bundles (as pluginval would be).
juce::String bundleOverride(const char* variable)
{
    const char* value = std::getenv(variable);
    return value != nullptr ? juce::String(value) : juce::String();
}

juce::File vst3Bundle()
{
    if (const auto path = bundleOverride("ROSIN_PLUGINHOST_VST3"); path.isNotEmpty())
        return juce::File(path);
    // The target's file is Rosin.vst3/Contents/<arch>-linux/Rosin.so.
    return juce::File(ROSIN_VST3_BINARY_DIR).getParentDirectory().getParentDirectory();
}

juce::File lv2Bundle()
{
    if (const auto path = bundleOverride("ROSIN_PLUGINHOST_LV2"); path.isNotEmpty())
        return juce::File(path);
    return juce::File(ROSIN_LV2_BUNDLE_DIR);
}

/// Scans the format's bundle as a host's plugin scanner would; an empty description (with the reason in
/// `why`) if nothing was found.
juce::PluginDescription scan(const juce::String& formatName, juce::String& why)
{
    auto* f = format(formatName);
    if (f == nullptr)
    {
        why = "format " + formatName + " not registered";
        return {};
    }
    juce::OwnedArray<juce::PluginDescription> found;
    if (formatName == "VST3")
    {
        const auto bundle = vst3Bundle();
        if (!bundle.isDirectory())
        {
            why = "no bundle at " + bundle.getFullPathName();
            return {};
        }
        if (!f->fileMightContainThisPluginType(bundle.getFullPathName()))
            why = "VST3PluginFormat does not recognise " + bundle.getFullPathName();
        f->findAllTypesForFile(found, bundle.getFullPathName());
    }
    else
    {
        const auto bundle = lv2Bundle();
        if (!bundle.getChildFile("manifest.ttl").existsAsFile())
        {
            why = "no manifest.ttl in " + bundle.getFullPathName();
            return {};
        }
        // LV2 plugins are found by URI once their bundle's folder has been searched.
        const auto uris = f->searchPathsForPlugins(
            juce::FileSearchPath(bundle.getParentDirectory().getFullPathName()), false, false);
        if (!uris.contains(ROSIN_LV2_URI))
            why = "LV2 world does not list " + juce::String(ROSIN_LV2_URI) + " after loading " +
                  bundle.getFullPathName() + "; it lists: " + uris.joinIntoString(", ");
        f->findAllTypesForFile(found, ROSIN_LV2_URI);
    }
    if (found.size() != 1)
    {
        why += " (" + juce::String(found.size()) + " plugin descriptions found)";
        return {};
    }
    return *found[0];
}

const juce::PluginDescription& description(const juce::String& formatName)
{
    static std::map<juce::String, juce::PluginDescription> cache;
    static std::map<juce::String, juce::String> reasons;
    if (cache.count(formatName) == 0)
        cache[formatName] = scan(formatName, reasons[formatName]);
    if (cache[formatName].fileOrIdentifier.isEmpty())
        ADD_FAILURE() << formatName << " bundle not loadable: " << reasons[formatName];
    return cache[formatName];
}

/// Lets the host's message thread run (JUCE's VST3 host syncs its edit-controller there, timers fire).
void pumpMessages(int milliseconds)
{
    juce::MessageManager::getInstance()->runDispatchLoopUntil(milliseconds);
}

/// JUCE's LV2 host re-instantiates the plugin on every prepareToPlay; the other tests give an LV2 instance
/// time to finish an instrument rebuild after it is made or prepared, so that they test one thing each;
/// PluginHostLv2.SurvivesPrepareWhileRebuilding runs without the delay.
bool settleLv2 = true;
constexpr int kLv2SettleMilliseconds = 400;

void settle(juce::AudioPluginInstance& plugin)
{
    if (settleLv2 && plugin.getPluginDescription().pluginFormatName == "LV2")
        pumpMessages(kLv2SettleMilliseconds);
}

void prepare(juce::AudioPluginInstance& plugin, double sampleRate, int blockSize)
{
    // prepareToPlay alone, as hosts and pluginval call it: setting the rate and block size first made JUCE's
    // VST3 host skip its re-setup when prepared again without a release (its "nothing changed" shortcut),
    // leaving its buffers at the old block size (a crash in the wrapper's validateLayouts, the host's doing).
    plugin.prepareToPlay(sampleRate, blockSize);
    settle(plugin);
}

/// Deletes an instance (after letting an LV2 one settle, see settleLv2).
void destroy(std::unique_ptr<juce::AudioPluginInstance>& plugin)
{
    if (plugin != nullptr)
        settle(*plugin);
    plugin.reset();
}

std::unique_ptr<juce::AudioPluginInstance> createInstance(const juce::String& formatName, double sampleRate,
                                                          int blockSize)
{
    const auto& desc = description(formatName);
    if (desc.fileOrIdentifier.isEmpty())
        return nullptr;
    juce::String error;
    auto instance = formats().createPluginInstance(desc, sampleRate, blockSize, error);
    EXPECT_NE(instance, nullptr) << formatName << ": createPluginInstance failed: " << error;
    pumpMessages();
    if (instance != nullptr)
        settle(*instance);
    return instance;
}

// --- rendering
// ----------------------------------------------------------------------------------------------

Render render(juce::AudioPluginInstance& plugin, const RenderPlan& plan)
{
    Render r;
    r.numChannels = std::max(plugin.getTotalNumInputChannels(), plugin.getTotalNumOutputChannels());
    const int maxBlock = *std::max_element(plan.blockSizes.begin(), plan.blockSizes.end());
    juce::AudioBuffer<float> buffer(r.numChannels, maxBlock);
    juce::MidiBuffer midi;
    double noteEnergy = 0.0;
    long noteSamples = 0;
    const int outChannels = plugin.getTotalNumOutputChannels();
    int position = 0;
    for (int block = 0; position < plan.totalSamples; ++block)
    {
        const int n = std::min(plan.blockSizes[static_cast<std::size_t>(block) % plan.blockSizes.size()],
                               plan.totalSamples - position);
        if (plan.beforeBlock)
            plan.beforeBlock(block);
        buffer.setSize(r.numChannels, n, false, false, true);
        buffer.clear();
        midi.clear();
        if (plan.noteOnAt >= position && plan.noteOnAt < position + n)
            midi.addEvent(juce::MidiMessage::noteOn(1, kNote, static_cast<juce::uint8>(100)),
                          plan.noteOnAt - position);
        if (plan.noteOffAt >= position && plan.noteOffAt < position + n)
            midi.addEvent(juce::MidiMessage::noteOff(1, kNote), plan.noteOffAt - position);
        plugin.processBlock(buffer, midi);
        for (int c = 0; c < outChannels; ++c)
        {
            const float* x = buffer.getReadPointer(c);
            for (int i = 0; i < n; ++i)
            {
                const float v = x[i];
                r.samples.push_back(v);
                if (!std::isfinite(v))
                {
                    ++r.nonFinite;
                    continue;
                }
                r.peak = std::max(r.peak, std::abs(v));
                const int t = position + i;
                if (plan.noteOnAt >= 0 && t >= plan.noteOnAt && (plan.noteOffAt < 0 || t < plan.noteOffAt))
                {
                    noteEnergy += static_cast<double>(v) * v;
                    ++noteSamples;
                }
            }
        }
        position += n;
    }
    r.rmsDuringNote = noteSamples > 0 ? std::sqrt(noteEnergy / static_cast<double>(noteSamples)) : 0.0;
    return r;
}

RenderPlan notePlan(double sampleRate, std::vector<int> blockSizes, double seconds, double noteSeconds)
{
    RenderPlan plan;
    plan.totalSamples = static_cast<int>(seconds * sampleRate);
    plan.blockSizes = std::move(blockSizes);
    plan.noteOnAt = 0;
    plan.noteOffAt = static_cast<int>(noteSeconds * sampleRate);
    return plan;
}

void releaseFormats()
{
    formatManager.reset();
}

std::vector<int> pluginParameters(juce::AudioPluginInstance& plugin)
{
    std::vector<int> indices;
    for (auto* p : plugin.getParameters())
        if (p->isAutomatable() && p != plugin.getBypassParameter() && p->getName(64) != "Program")
            indices.push_back(p->getParameterIndex());
    return indices;
}

} // namespace rosin::pluginhost
