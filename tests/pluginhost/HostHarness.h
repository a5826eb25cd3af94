#pragma once
// The host harness of the plugin-hosting tests (PluginHostTest.cpp): JUCE's VST3 and LV2 hosting classes
// pointed at the bundles this build made (or at $ROSIN_PLUGINHOST_VST3 / $ROSIN_PLUGINHOST_LV2), and a
// renderer that plays one MIDI note through an instance block by block.
#include <functional>
#include <memory>
#include <vector>

#include <juce_audio_processors/juce_audio_processors.h>

namespace rosin::pluginhost
{

inline constexpr int kNote = 62;            // D4: on every string instrument's range (violin, viola, cello)
inline constexpr float kOutputBound = 1.0f; // the processor clamps its output to +-1
inline constexpr float kSilenceRms = 1.0e-5f;

/// The format manager with VST3 and LV2; made on first use under the test's message manager.
juce::AudioPluginFormatManager& formats();
/// The registered format called `name` ("VST3" or "LV2"), registering both on first use; nullptr if unknown.
juce::AudioPluginFormat* format(const juce::String& name);
/// The scanned description of this build's bundle in that format ("VST3" or "LV2"); fails the test if absent.
const juce::PluginDescription& description(const juce::String& formatName);
/// Lets the host's message thread run (JUCE's VST3 host syncs its edit-controller there, timers fire).
void pumpMessages(int milliseconds = 5);
/// JUCE's LV2 host re-instantiates the plugin on every prepareToPlay; while true, LV2 instances are given
/// time to finish an instrument rebuild after they are made or prepared and before they are deleted.
extern bool settleLv2;
void prepare(juce::AudioPluginInstance& plugin, double sampleRate, int blockSize);
/// Deletes an instance (after letting an LV2 one settle, see settleLv2).
void destroy(std::unique_ptr<juce::AudioPluginInstance>& plugin);
std::unique_ptr<juce::AudioPluginInstance> createInstance(const juce::String& formatName,
                                                          double sampleRate = 48000.0, int blockSize = 512);

struct Render
{
    std::vector<float> samples; ///< channel after channel, block by block
    int numChannels = 0;
    int nonFinite = 0;
    float peak = 0.0f;
    double rmsDuringNote = 0.0;
};

struct RenderPlan
{
    int totalSamples = 0;
    std::vector<int> blockSizes{512};           ///< cycled
    int noteOnAt = 0;                           ///< sample, or -1
    int noteOffAt = -1;                         ///< sample, or -1
    std::function<void(int block)> beforeBlock; ///< e.g. parameter fuzzing between blocks
};

/// Plays plan through the instance and collects every output sample.
Render render(juce::AudioPluginInstance& plugin, const RenderPlan& plan);
/// A note from sample 0 to noteSeconds, rendered for `seconds` with the given block sizes.
RenderPlan notePlan(double sampleRate, std::vector<int> blockSizes, double seconds = 0.4,
                    double noteSeconds = 0.3);
/// The plugin's own parameters: not the host-made ones (JUCE's VST3 wrapper adds bypass, a program-change
/// parameter and 2048 non-automatable "MIDI CC" parameters), which a preset does not hold.
std::vector<int> pluginParameters(juce::AudioPluginInstance& plugin);

/// Frees the format manager (before JUCE's message manager goes).
void releaseFormats();

} // namespace rosin::pluginhost
