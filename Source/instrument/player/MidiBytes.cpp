#include "instrument/player/MidiBytes.h"

namespace rosin::player
{

bool decodeMidi(const std::uint8_t* data, int size, int sampleOffset, GestureEvent& out) noexcept
{
    if (data == nullptr || size < 2)
        return false;
    const int status = data[0] & 0xF0;
    const int channel = (data[0] & 0x0F) + 1;
    const int d1 = data[1] & 0x7F;
    const int d2 = size >= 3 ? data[2] & 0x7F : 0;
    const bool threeBytes = size >= 3;
    GestureEvent e;
    e.sampleOffset = sampleOffset;
    e.channel = channel;
    switch (status)
    {
    case 0x80:
        if (!threeBytes)
            return false;
        e.type = GestureEvent::Type::NoteOff;
        e.number = d1;
        break;
    case 0x90:
        if (!threeBytes)
            return false;
        e.type = d2 > 0 ? GestureEvent::Type::NoteOn : GestureEvent::Type::NoteOff;
        e.number = d1;
        e.value = d2;
        break;
    case 0xA0:
        if (!threeBytes)
            return false;
        e.type = GestureEvent::Type::PolyPressure;
        e.number = d1;
        e.value = d2;
        break;
    case 0xB0:
        if (!threeBytes)
            return false;
        e.type = GestureEvent::Type::Controller;
        e.number = d1;
        e.value = d2;
        break;
    case 0xD0:
        e.type = GestureEvent::Type::ChannelPressure;
        e.value = d1;
        break;
    case 0xE0:
        if (!threeBytes)
            return false;
        e.type = GestureEvent::Type::PitchBend;
        e.value = d1 | (d2 << 7);
        break;
    default:
        return false;
    }
    out = e;
    return true;
}

} // namespace rosin::player
