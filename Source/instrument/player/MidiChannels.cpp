#include "instrument/player/MidiChannels.h"

#include <algorithm>

#include "instrument/player/GestureParameters.h"

namespace rosin::player
{

std::size_t MidiChannels::index(int channel) noexcept
{
    return static_cast<std::size_t>(std::clamp(channel, 1, kChannels) - 1);
}

void MidiChannels::resetControllers() noexcept
{
    for (auto& c : channels_)
        c.resetControllers();
}

void MidiChannels::controller(int channel, int number, int value) noexcept
{
    if (!valid(channel))
        return;
    auto& state = channels_[index(channel)];
    const int rpn = state.controller(number, value);
    if (rpn == MidiChannelState::kRpnMpeConfiguration && number == MidiChannelState::kCcDataEntryMsb &&
        channel == kMasterChannel)
        configureLowerZone(state.dataEntry());
    else if (rpn == MidiChannelState::kRpnPitchBendSensitivity && isMemberChannel(channel))
        // MPE: a member channel's bend range is the zone's; the sender may set it on any one member channel.
        for (int c = kMasterChannel + 1; c <= kMasterChannel + memberCount_; ++c)
            channels_[index(c)].setBendRange(state.bendRange());
}

void MidiChannels::pressure(int channel, int value) noexcept
{
    if (valid(channel))
        channels_[index(channel)].setPressure(value);
}

void MidiChannels::pitchBend(int channel, int value14) noexcept
{
    if (valid(channel))
        channels_[index(channel)].setPitchBend(value14);
}

void MidiChannels::configureLowerZone(int memberCount) noexcept
{
    memberCount_ = std::clamp(memberCount, 0, kChannels - 1);
    for (int c = 1; c <= kChannels; ++c)
        channels_[index(c)].setBendRange(isMemberChannel(c) ? midimap::mpeMemberPitchBendSemitones
                                                            : midimap::pitchBendSemitones);
}

ChannelControls MidiChannels::controls(int channel) const noexcept
{
    const auto& own = channels_[index(channel)];
    ChannelControls c;
    c.force = own.forceFactor();
    c.pressure = own.pressureFactor();
    c.speed = own.speedFactor();
    c.beta = own.betaFactor();
    c.finger = own.fingerFactor();
    c.dynamics = own.dynamics();
    c.vibrato = own.vibrato();
    c.bowPressure = own.bowPressure();
    c.vibratoRate = own.vibratoRateFactor();
    c.vibratoDelay = own.vibratoDelayFactor();
    c.tremolo = own.tremolo();
    if (isMemberChannel(channel))
    {
        const auto& master = channels_[index(kMasterChannel)];
        const auto ownOrMaster = [](double mine, double masters) { return mine >= 0.0 ? mine : masters; };
        c.dynamics = ownOrMaster(c.dynamics, master.dynamics());
        c.vibrato = ownOrMaster(c.vibrato, master.vibrato());
        c.bowPressure = ownOrMaster(c.bowPressure, master.bowPressure());
        c.vibratoRate *= master.vibratoRateFactor();
        c.vibratoDelay *= master.vibratoDelayFactor();
        c.tremolo = c.tremolo || master.tremolo();
        c.force *= master.forceFactor() * master.pressureFactor();
        c.speed *= master.speedFactor();
        c.beta *= master.betaFactor();
        c.finger *= master.fingerFactor(); // the bends add in semitones
    }
    return c;
}

} // namespace rosin::player
