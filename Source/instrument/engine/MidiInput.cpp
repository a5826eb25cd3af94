#include "instrument/engine/MidiInput.h"

#include <stdexcept>

#include "instrument/player/MidiBytes.h"

namespace rosin::engine
{

juce::MidiMessageSequence readMidiFile(const juce::File& file)
{
    juce::FileInputStream in(file);
    if (!in.openedOk())
        throw std::runtime_error(file.getFullPathName().toStdString() + ": cannot open the MIDI file");
    return readMidiStream(in, file.getFullPathName().toStdString());
}

juce::MidiMessageSequence readMidiStream(juce::InputStream& in, const std::string& name)
{
    juce::MidiFile midi;
    if (!midi.readFrom(in))
        throw std::runtime_error(name + ": not a standard MIDI file");
    midi.convertTimestampTicksToSeconds();
    juce::MidiMessageSequence merged;
    for (int t = 0; t < midi.getNumTracks(); ++t)
        merged.addSequence(*midi.getTrack(t), 0.0);
    merged.updateMatchedPairs();
    return merged;
}

bool MidiBufferEvents::next(int sample, player::GestureEvent& event) noexcept
{
    while (next_ != end_ && (*next_).samplePosition <= sample)
        if (decode(sample, event))
            return true;
    return false;
}

bool MidiBufferEvents::remaining(int sample, player::GestureEvent& event) noexcept
{
    while (next_ != end_)
        if (decode(sample, event))
            return true;
    return false;
}

bool MidiBufferEvents::decode(int sample, player::GestureEvent& event) noexcept
{
    const auto m = *next_;
    ++next_;
    return player::decodeMidi(m.data, m.numBytes, sample, event);
}

} // namespace rosin::engine
