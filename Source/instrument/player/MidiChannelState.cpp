#include "instrument/player/MidiChannelState.h"

#include <algorithm>
#include <cmath>

#include "instrument/player/GestureParameters.h"

namespace rosin::player
{
namespace
{
constexpr int ccNrpnLsb = 98;
constexpr int ccNrpnMsb = 99;
constexpr int ccRpnLsb = 100;
constexpr int ccRpnMsb = 101;
constexpr int rpnNull = 127;
} // namespace

void MidiChannelState::resetAll(double bendRangeSemitones) noexcept
{
    resetControllers();
    dataEntry_ = 0;
    setBendRange(bendRangeSemitones);
}

void MidiChannelState::resetControllers() noexcept
{
    ccForce_ = ccSpeed_ = ccBeta_ = ccSlide_ = 64;
    forceFactor_ = pressureFactor_ = speedFactor_ = betaFactor_ = 1.0;
    dynamics_ = vibrato_ = bowPressure_ = -1.0;
    vibratoRateFactor_ = vibratoDelayFactor_ = 1.0;
    tremolo_ = false;
    rpnMsb_ = rpnLsb_ = rpnNull;
    pitchBend_ = 8192;
    updateBend();
}

int MidiChannelState::selectedRpn() const noexcept
{
    if (rpnMsb_ == rpnNull && rpnLsb_ == rpnNull)
        return kNoRpn;
    return rpnMsb_ * 128 + rpnLsb_;
}

int MidiChannelState::controller(int number, int value) noexcept
{
    value = std::clamp(value, 0, 127);
    switch (number)
    {
    case midimap::ccForce:
        ccForce_ = value;
        forceFactor_ = midimap::controllerFactor(value);
        vibrato_ = value / 127.0;
        break;
    case midimap::ccSpeed:
    case midimap::ccSpeedAlt:
        ccSpeed_ = value;
        speedFactor_ = midimap::controllerFactor(value);
        dynamics_ = value / 127.0;
        break;
    case midimap::ccBowPressure:
        bowPressure_ = value / 127.0;
        break;
    case midimap::ccVibratoRate:
        vibratoRateFactor_ = std::exp2((value - 64) / 128.0);
        break;
    case midimap::ccVibratoDelay:
        vibratoDelayFactor_ = std::exp2((value - 64) / 32.0);
        break;
    case midimap::ccTremolo:
        tremolo_ = value >= 64;
        break;
    case midimap::ccBeta:
        ccBeta_ = value;
        updateBeta();
        break;
    case midimap::ccSlide:
        ccSlide_ = value;
        updateBeta();
        break;
    case ccRpnMsb:
        rpnMsb_ = value;
        break;
    case ccRpnLsb:
        rpnLsb_ = value;
        break;
    case ccNrpnMsb:
    case ccNrpnLsb:
        // Data entry now belongs to an NRPN, which Rosin does not use: it must not change an RPN.
        rpnMsb_ = rpnLsb_ = rpnNull;
        break;
    case kCcDataEntryMsb:
    {
        const int rpn = selectedRpn();
        if (rpn == kNoRpn)
            break;
        dataEntry_ = value;
        if (rpn == kRpnPitchBendSensitivity)
            setBendRange(value); // the MSB alone means whole semitones: the cents restart at 0
        return rpn;
    }
    case kCcDataEntryLsb:
    {
        const int rpn = selectedRpn();
        if (rpn == kNoRpn)
            break;
        if (rpn == kRpnPitchBendSensitivity)
            setBendRange(std::floor(bendRange_) + std::min(value, 99) / 100.0);
        return rpn;
    }
    case midimap::ccResetAll:
        resetControllers();
        break;
    default:
        break;
    }
    return kNoRpn;
}

void MidiChannelState::setPressure(int value) noexcept
{
    pressureFactor_ = midimap::controllerFactor(value);
    bowPressure_ = std::clamp(value, 0, 127) / 127.0;
}

void MidiChannelState::setPitchBend(int value14) noexcept
{
    pitchBend_ = std::clamp(value14, 0, 16383);
    updateBend();
}

void MidiChannelState::setBendRange(double semitones) noexcept
{
    bendRange_ = std::clamp(semitones, 0.0, 127.99);
    updateBend();
}

void MidiChannelState::updateBeta() noexcept
{
    betaFactor_ = midimap::betaControllerFactor(ccBeta_) * midimap::betaControllerFactor(ccSlide_);
}

void MidiChannelState::updateBend() noexcept
{
    bendSemitones_ = (pitchBend_ - 8192) / 8192.0 * bendRange_;
    fingerFactor_ = std::exp2(-bendSemitones_ / 12.0);
}

} // namespace rosin::player
