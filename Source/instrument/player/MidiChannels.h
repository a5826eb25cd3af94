#pragma once
// The 16 MIDI channels' controllers and the MPE lower zone that combines them (JUCE-free, allocation-free,
// noexcept).
//
// Without MPE every channel is independent: a note gets the controllers of the channel it was played on (a
// keyboard on one channel behaves as if channels did not exist).
// MPE lower zone (MIDI Polyphonic Expression 1.0): the MPE Configuration Message (RPN 6 on channel 1, data
// entry N) makes channel 1 the master channel and channels 2..N+1 member channels (N = 0 ends MPE). A member
// channel carries one note's own pitch bend (default range +-48 semitones), pressure and CC74; the master
// channel's controllers (bend range +-2) apply to every member channel on top of them: factors multiply,
// bends add in semitones.
#include <array>
#include <cstddef>

#include "instrument/player/MidiChannelState.h"

namespace rosin::player
{

/// The controller factors a note on some channel gets (all 1 at the reset values).
struct ChannelControls
{
    double force = 1.0;    ///< CC1 (and, in an MPE zone, the master channel's pressure)
    double pressure = 1.0; ///< the note channel's own pressure; poly pressure for the note replaces it
    double speed = 1.0;
    double beta = 1.0;
    double finger = 1.0; ///< pitch bend as a finger multiplier
    // The musical mapping's (MidiChannelState): -1 until received; a member channel's own, else the master's.
    double dynamics = -1.0, vibrato = -1.0, bowPressure = -1.0;
    double vibratoRate = 1.0, vibratoDelay = 1.0; ///< factors
    bool tremolo = false;
};

class MidiChannels
{
  public:
    static constexpr int kChannels = 16;
    static constexpr int kMasterChannel = 1; ///< the lower zone's master channel

    /// Every channel's controllers to their reset values. Keeps the zone and the bend ranges (configuration,
    /// which hosts and MPE controllers send once, not with every note).
    void resetControllers() noexcept;

    /// Channel messages; channel 1..16 (others are ignored).
    void controller(int channel, int number, int value) noexcept;
    void pressure(int channel, int value) noexcept;
    void pitchBend(int channel, int value14) noexcept;

    /// The lower zone with memberCount member channels (0: MPE off, 1..15). Sets the bend ranges to the MPE
    /// defaults: master +-2, members +-48, other channels +-2.
    void configureLowerZone(int memberCount) noexcept;

    bool mpeEnabled() const noexcept { return memberCount_ > 0; }
    int memberChannelCount() const noexcept { return memberCount_; }
    bool isMemberChannel(int channel) const noexcept
    {
        return memberCount_ > 0 && channel > kMasterChannel && channel <= kMasterChannel + memberCount_;
    }
    /// Channel 1..16 (clamped).
    const MidiChannelState& channel(int channel) const noexcept { return channels_[index(channel)]; }

    /// What a note on `channel` gets: its channel's controllers, combined with the master channel's when
    /// it is a member channel.
    ChannelControls controls(int channel) const noexcept;

  private:
    static std::size_t index(int channel) noexcept;
    static bool valid(int channel) noexcept { return channel >= 1 && channel <= kChannels; }

    std::array<MidiChannelState, kChannels> channels_{};
    int memberCount_ = 0;
};

} // namespace rosin::player
