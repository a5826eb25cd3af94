#pragma once
// Shared helpers of the plugin tests: the demo phrase, renders through a fresh processor, signal checks.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/config/PresetLoader.h"
#include "instrument/plugin/HostRender.h"
#include "instrument/plugin/RosinProcessor.h"

namespace rosin::test
{

/// The factory presets the plugin offers as programs: every preset but a rig's ([Smith2000]'s oscillator).
inline std::vector<std::string> instrumentPresetNames()
{
    std::vector<std::string> names;
    for (const auto& name : config::presetNames())
        if (!config::loadPreset(name).rig)
            names.push_back(name);
    return names;
}

inline const juce::MidiMessageSequence& demoPhrase()
{
    static const juce::MidiMessageSequence sequence = engine::readMidiFile(juce::File(ROSIN_DEMO_MIDI));
    return sequence;
}

inline engine::MidiRenderResult renderDemo(const std::string& program, double sampleRate, int blockSize,
                                           double tailSeconds = 1.0)
{
    plugin::RosinProcessor processor;
    if (!program.empty())
        processor.setProgramByName(program);
    engine::MidiRenderSettings settings;
    settings.sampleRate = sampleRate;
    settings.blockSize = blockSize;
    settings.tailSeconds = tailSeconds;
    return test::renderMidi(processor, demoPhrase(), settings);
}

/// One note at velocity 80 held for `seconds` from the start, then `tailSeconds` more, through `processor` as
/// it is set up (program, parameters); 48 kHz.
inline std::vector<float> renderHeldNote(plugin::RosinProcessor& processor, int note, double seconds,
                                         double tailSeconds)
{
    juce::MidiMessageSequence seq;
    seq.addEvent(juce::MidiMessage::noteOn(1, note, static_cast<juce::uint8>(80)), 0.0);
    seq.addEvent(juce::MidiMessage::noteOff(1, note), seconds);
    engine::MidiRenderSettings settings;
    settings.sampleRate = 48000.0;
    settings.tailSeconds = tailSeconds;
    return test::renderMidi(processor, seq, settings).audio;
}

inline void setParameter(plugin::RosinProcessor& p, const char* id, float plainValue)
{
    auto* parameter = p.parameters().getParameter(id);
    parameter->setValueNotifyingHost(parameter->convertTo0to1(plainValue));
}

/// A temporary folder for a test's files, removed with everything in it at the end of its scope.
struct TempFolder
{
    juce::TemporaryFile dir{"rosin-plugin-test"};
    juce::File folder() const
    {
        const juce::File f = dir.getFile();
        f.createDirectory();
        return f;
    }
    ~TempFolder() { dir.getFile().deleteRecursively(); }
};

inline bool allFinite(const std::vector<float>& x)
{
    for (float v : x)
        if (!std::isfinite(v))
            return false;
    return true;
}

} // namespace rosin::test
