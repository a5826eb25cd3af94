#include "instrument/plugin/KeyboardQueue.h"

#include <algorithm>
#include <cmath>

namespace rosin::plugin
{

namespace
{
std::uint8_t dataByte(int value)
{
    return static_cast<std::uint8_t>(std::clamp(value, 0, 127));
}
std::uint8_t statusByte(int kind, int channel)
{
    return static_cast<std::uint8_t>(kind | (std::clamp(channel, 1, 16) - 1));
}
} // namespace

void KeyboardQueue::handleNoteOn(juce::MidiKeyboardState*, int channel, int note, float velocity)
{
    // A velocity that rounds to 0 would read as a note-off.
    const int v = std::max(1, static_cast<int>(std::lround(velocity * 127.0f)));
    push({statusByte(0x90, channel), dataByte(note), dataByte(v)});
}

void KeyboardQueue::handleNoteOff(juce::MidiKeyboardState*, int channel, int note, float)
{
    push({statusByte(0x80, channel), dataByte(note), 0});
}

void KeyboardQueue::push(const Message& m) noexcept
{
    const auto scope = fifo_.write(1);
    if (scope.blockSize1 > 0)
        messages_[static_cast<std::size_t>(scope.startIndex1)] = m;
    else if (scope.blockSize2 > 0)
        messages_[static_cast<std::size_t>(scope.startIndex2)] = m;
}

} // namespace rosin::plugin
