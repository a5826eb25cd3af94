#pragma once
// The plugin's processor driven as a host drives it, offline: a MIDI sequence (timestamps in seconds) and
// optional automation lanes, cut into blocks of any size, parameters set through the host's parameter objects
// and engine builds serviced between blocks, as the message thread's timer would. The tests' host; the
// command line renders through engine::OfflineInstrument, which tests/instrument/plugin/OfflineRenderTest.cpp
// holds to this output bit for bit.
#include <juce_audio_basics/juce_audio_basics.h>

#include "instrument/engine/AutomationLanes.h"
#include "instrument/engine/MidiInput.h"
#include "instrument/engine/OfflineInstrument.h"
#include "instrument/plugin/RosinProcessor.h"

namespace rosin::test
{

/// Renders through `processor` (programs and parameters as set by the caller; prepareToPlay is called here).
/// Builds requested by automation (friction, instrument, ...) are done between blocks, at grid points.
engine::MidiRenderResult renderMidi(plugin::RosinProcessor& processor,
                                    const juce::MidiMessageSequence& sequence,
                                    const engine::MidiRenderSettings& settings,
                                    const engine::AutomationLanes* automation = nullptr);

} // namespace rosin::test
