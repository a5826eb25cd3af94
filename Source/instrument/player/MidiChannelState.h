#pragma once
// One MIDI channel's controllers as the gesture controller reads them (JUCE-free, allocation-free, noexcept):
// the bow controllers, channel pressure, pitch bend and its range, and the RPN selection through which the
// range (RPN 0) and the MPE zone (RPN 6, handled by MidiChannels) are set.
//
// The factors are recomputed when a value arrives, not when they are read: next() reads them every sample
// for every string.

namespace rosin::player
{

class MidiChannelState
{
  public:
    static constexpr int kNoRpn = -1;
    static constexpr int kRpnPitchBendSensitivity = 0;
    static constexpr int kRpnMpeConfiguration = 6;
    static constexpr int kCcDataEntryMsb = 6;
    static constexpr int kCcDataEntryLsb = 38;

    /// Every controller and the bend range at their defaults, no RPN selected.
    void resetAll(double bendRangeSemitones) noexcept;
    /// Reset All Controllers (CC121, RP-015): values to their reset values, RPN deselected; the bend range,
    /// an RPN setting, is kept.
    void resetControllers() noexcept;

    /// A control change (value 0..127). Returns the selected RPN when the message was a data entry (CC6 or
    /// CC38) for it, else kNoRpn; RPN 0 is applied here, the caller handles the others.
    int controller(int number, int value) noexcept;
    void setPressure(int value) noexcept;
    /// value14 0..16383, 8192 = centre.
    void setPitchBend(int value14) noexcept;
    void setBendRange(double semitones) noexcept;

    /// CC1: bow force factor.
    double forceFactor() const noexcept { return forceFactor_; }
    /// Channel pressure: force factor, 1 until pressure is received.
    double pressureFactor() const noexcept { return pressureFactor_; }
    /// CC11 or CC2 (the last received): bow speed factor.
    double speedFactor() const noexcept { return speedFactor_; }
    /// CC21 x CC74 (MPE slide): beta factor.
    double betaFactor() const noexcept { return betaFactor_; }
    /// Finger multiplier 2^(-bend/12): bending up shortens the string.
    double fingerFactor() const noexcept { return fingerFactor_; }
    double bendSemitones() const noexcept { return bendSemitones_; }
    double bendRange() const noexcept { return bendRange_; }
    // The musical mapping's controllers, 0..1 (value / 127), or -1 until one arrives (the parameter rules):
    /// CC11 or CC2 (the last received): dynamics.
    double dynamics() const noexcept { return dynamics_; }
    /// CC1: vibrato depth.
    double vibrato() const noexcept { return vibrato_; }
    /// CC20 or channel pressure (the last received): bow pressure.
    double bowPressure() const noexcept { return bowPressure_; }
    /// CC76: vibrato rate factor 2^((value - 64) / 128), 1 at the reset value.
    double vibratoRateFactor() const noexcept { return vibratoRateFactor_; }
    /// CC78: vibrato delay factor 2^((value - 64) / 32), 1 at the reset value.
    double vibratoDelayFactor() const noexcept { return vibratoDelayFactor_; }
    /// CC17 >= 64: tremolo.
    bool tremolo() const noexcept { return tremolo_; }
    /// The last data-entry MSB (CC6) value.
    int dataEntry() const noexcept { return dataEntry_; }

  private:
    int selectedRpn() const noexcept;
    void updateBeta() noexcept;
    void updateBend() noexcept;

    int ccForce_ = 64, ccSpeed_ = 64, ccBeta_ = 64, ccSlide_ = 64;
    int pitchBend_ = 8192;
    double bendRange_ = 2.0;
    int rpnMsb_ = 127, rpnLsb_ = 127; // 127/127: RPN null, nothing selected
    int dataEntry_ = 0;
    double forceFactor_ = 1.0, pressureFactor_ = 1.0, speedFactor_ = 1.0, betaFactor_ = 1.0;
    double fingerFactor_ = 1.0, bendSemitones_ = 0.0;
    double dynamics_ = -1.0, vibrato_ = -1.0, bowPressure_ = -1.0;
    double vibratoRateFactor_ = 1.0, vibratoDelayFactor_ = 1.0;
    bool tremolo_ = false;
};

} // namespace rosin::player
