#pragma once
// Notes played on the editor's on-screen keyboard (or the computer keyboard through it) reach the audio
// thread through a lock-free single-producer single-consumer queue: the keyboard state's listener runs on
// the message thread and pushes 3-byte MIDI messages; processBlock drains them at the start of a block.
// juce::MidiKeyboardState::processNextMidiBuffer would take a lock on the audio thread, and adding to the
// host's MidiBuffer can allocate; neither happens here.
#include <array>
#include <cstdint>

#include <juce_audio_basics/juce_audio_basics.h>

namespace rosin::plugin
{

class KeyboardQueue : public juce::MidiKeyboardState::Listener
{
  public:
    static constexpr int kCapacity = 256;
    using Message = std::array<std::uint8_t, 3>;

    // Message thread (the keyboard's). A full queue drops the note: the player sees the key and plays again.
    void handleNoteOn(juce::MidiKeyboardState*, int channel, int note, float velocity) override;
    void handleNoteOff(juce::MidiKeyboardState*, int channel, int note, float velocity) override;

    /// Audio thread: calls f(const std::uint8_t* bytes, int size) for every queued message, oldest first.
    template <typename F> void drain(F&& f) noexcept
    {
        const auto scope = fifo_.read(fifo_.getNumReady());
        for (int i = 0; i < scope.blockSize1; ++i)
            f(messages_[static_cast<std::size_t>(scope.startIndex1 + i)].data(), 3);
        for (int i = 0; i < scope.blockSize2; ++i)
            f(messages_[static_cast<std::size_t>(scope.startIndex2 + i)].data(), 3);
    }

  private:
    void push(const Message& m) noexcept;
    juce::AbstractFifo fifo_{kCapacity};
    std::array<Message, kCapacity> messages_{};
};

} // namespace rosin::plugin
