#pragma once
// A MIDI-like performance event for MidiGestureController, already decoded from bytes (JUCE-free, so the
// gesture layer and its tests never see a juce::MidiMessage). The plugin and the offline renderer translate
// their MIDI into these; `sampleOffset` is where in the current block the event takes effect.
#include <cstdint>

namespace rosin::player
{

struct GestureEvent
{
    enum class Type : std::uint8_t
    {
        NoteOn,          ///< number = note, value = velocity 1..127 (0 is treated as NoteOff)
        NoteOff,         ///< number = note
        Controller,      ///< number = CC number, value 0..127
        ChannelPressure, ///< value 0..127
        PolyPressure,    ///< number = note, value 0..127
        PitchBend        ///< value 0..16383, 8192 = centre
    };

    Type type = Type::NoteOn;
    int sampleOffset = 0; ///< sample index within the block at which the event applies
    int channel = 1;      ///< MIDI channel 1..16: a note's controllers are its channel's (MPE: per note)
    int number = 0;
    int value = 0;

    /// The same event on another channel: GestureEvent::noteOn(60, 100).onChannel(2).
    GestureEvent onChannel(int midiChannel) const noexcept
    {
        GestureEvent e = *this;
        e.channel = midiChannel;
        return e;
    }

    static GestureEvent noteOn(int note, int velocity, int offset = 0)
    {
        return {Type::NoteOn, offset, 1, note, velocity};
    }
    static GestureEvent noteOff(int note, int offset = 0) { return {Type::NoteOff, offset, 1, note, 0}; }
    static GestureEvent controller(int cc, int value, int offset = 0)
    {
        return {Type::Controller, offset, 1, cc, value};
    }
    static GestureEvent channelPressure(int value, int offset = 0)
    {
        return {Type::ChannelPressure, offset, 1, 0, value};
    }
    static GestureEvent polyPressure(int note, int value, int offset = 0)
    {
        return {Type::PolyPressure, offset, 1, note, value};
    }
    static GestureEvent pitchBend(int value14, int offset = 0)
    {
        return {Type::PitchBend, offset, 1, 0, value14};
    }
};

} // namespace rosin::player
