#pragma once
// MIDI into the performer: standard MIDI files as one sequence (the offline render, the tests), and a block's
// juce::MidiBuffer as the performer's event source (the plugin's processBlock, the offline render), decoded
// as the performer reaches each event's sample.
#include <string>

#include <juce_audio_basics/juce_audio_basics.h>

#include "instrument/performer/Performer.h"

namespace rosin::engine
{

/// All tracks of a MIDI file merged into one sequence with timestamps in seconds (tempo map applied).
/// Throws std::runtime_error naming the file when it cannot be opened or is not a standard MIDI file.
juce::MidiMessageSequence readMidiFile(const juce::File& file);
/// The same from a stream; `name` names the source in errors (std::runtime_error).
juce::MidiMessageSequence readMidiStream(juce::InputStream& in, const std::string& name);

/// One block's MIDI, as the performer's events (undecodable messages are skipped). Never allocates.
class MidiBufferEvents final : public performer::EventSource
{
  public:
    explicit MidiBufferEvents(const juce::MidiBuffer& midi) noexcept : next_(midi.cbegin()), end_(midi.cend())
    {
    }
    bool next(int sample, player::GestureEvent& event) noexcept override;
    bool remaining(int sample, player::GestureEvent& event) noexcept override;

  private:
    bool decode(int sample, player::GestureEvent& event) noexcept;
    juce::MidiBufferIterator next_, end_;
};

} // namespace rosin::engine
