#pragma once
// Raw MIDI 1.0 channel-voice bytes -> GestureEvent (JUCE-free, allocation-free), so the plugin can read a
// juce::MidiBuffer's bytes without building juce::MidiMessage objects on the audio thread.
#include <cstdint>

#include "instrument/player/GestureEvent.h"

namespace rosin::player
{

/// Decodes one message. Returns false for anything the controller does not use (sysex, clock, program
/// change, malformed or truncated data); `out` is then unchanged.
bool decodeMidi(const std::uint8_t* data, int size, int sampleOffset, GestureEvent& out) noexcept;

} // namespace rosin::player
