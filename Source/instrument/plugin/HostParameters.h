#pragma once
// The engine's parameters (engine/EngineParameters.h) as the host's: the AudioProcessorValueTreeState's
// layout made from the engine's table, and direct pointers to its atomics, so the audio thread never looks a
// parameter up by string.
#include <array>
#include <atomic>

#include <juce_audio_processors/juce_audio_processors.h>

#include "instrument/engine/EngineParameters.h"

namespace rosin::plugin
{

namespace ids = engine::ids;

/// One host parameter per row of the engine's table (engine::makeParameters()).
juce::AudioProcessorValueTreeState::ParameterLayout createParameterLayout();

class ParameterReader
{
  public:
    explicit ParameterReader(juce::AudioProcessorValueTreeState& state);
    /// Audio thread safe: atomic loads only. stringCount maps the string choice to a string index.
    engine::ParameterSnapshot read(int stringCount) const noexcept
    {
        return engine::snapshotOf(load(), stringCount);
    }
    engine::InstrumentKey readKey() const noexcept { return engine::instrumentKeyOf(load()); }

  private:
    engine::RawParameterValues load() const noexcept;
    std::array<std::atomic<float>*, engine::kParameterCount> values_{};
};

} // namespace rosin::plugin
