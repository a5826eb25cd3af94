#pragma once
// Offline rendering through RosinProcessor: a MIDI sequence (timestamps in seconds) and optional automation
// lanes, cut into blocks of any size, exactly as a host would drive the plugin. Used by `rosin render --midi`
// and the plugin tests. Every event lands at its own sample and automation on a fixed control grid, so the
// result is bit-identical for every block size.
#include <vector>

#include <juce_audio_basics/juce_audio_basics.h>

#include "AutomationLanes.h"
#include "RosinProcessor.h"

namespace rosin::plugin
{

struct MidiRenderSettings
{
    double sampleRate = 48000.0;
    int blockSize = 512;
    double tailSeconds = 2.0; ///< rendered after the last event, so the strings ring down
    int controlInterval = 64; ///< automation grid, samples
};

struct MidiRenderResult
{
    std::vector<float> audio; ///< channel 0 (the plugin writes the same signal to every channel)
    float peak = 0.0f;
    int runawayResets = 0;
    int nonFiniteSamples = 0;
};

/// Renders through `processor` (programs and parameters as set by the caller; prepareToPlay is called here).
/// Builds requested by automation (friction, instrument, ...) are done between blocks, at grid points.
MidiRenderResult renderMidi(RosinProcessor& processor, const juce::MidiMessageSequence& sequence,
                            const MidiRenderSettings& settings, const AutomationLanes* automation = nullptr);

/// All tracks of a MIDI file merged into one sequence with timestamps in seconds (tempo map applied).
juce::MidiMessageSequence readMidiFile(const juce::File& file);
/// The same from a stream; `name` names the source in errors (std::runtime_error).
juce::MidiMessageSequence readMidiStream(juce::InputStream& in, const std::string& name);

} // namespace rosin::plugin
