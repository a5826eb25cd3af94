// MidiGestureController with MIDI channels: the MPE lower zone (per-note bend, pressure and slide, one string
// per member channel, the master channel on top), RPN 0 bend ranges, keyswitches, and single-channel playing
// on a channel other than 1. Expected values come from the MIDI map's formulas, not from earlier runs.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/physics/instrument/BowedInstrument.h"
#include "instrument/player/MidiBytes.h"
#include "instrument/player/MidiGestureController.h"
#include "instrument/player/StringChoice.h"

namespace rosin::player
{
namespace ROSIN_FILE_LOCAL
{

constexpr double kFs = 48000.0;
constexpr int kSettle = 4800;      // 100 ms: 33 smoothing time constants
constexpr int kLongSettle = 48000; // 1 s: the attack's extra force has relaxed too

std::vector<double> openFrequencies(const physics::InstrumentConfig& config)
{
    std::vector<double> f;
    for (const auto& s : config.strings)
        f.push_back(s.fundamental());
    return f;
}

struct Rig
{
    MidiGestureController controller;
    std::vector<double> open;
    std::array<physics::BowInput, MidiGestureController::kMaxStrings> in{};
    explicit Rig(const physics::InstrumentConfig& config = physics::celloInstrument(),
                 GestureParameters p = {})
        : open(openFrequencies(config))
    {
        controller.prepare(open.data(), static_cast<int>(open.size()), kFs);
        controller.setParameters(p);
    }
    void send(const GestureEvent& e) { controller.handleEvent(e); }
    void cc(int channel, int number, int value)
    {
        send(GestureEvent::controller(number, value).onChannel(channel));
    }
    void noteOn(int channel, int note, int velocity = 64)
    {
        send(GestureEvent::noteOn(note, velocity).onChannel(channel));
    }
    void noteOff(int channel, int note) { send(GestureEvent::noteOff(note).onChannel(channel)); }
    void bend(int channel, int value14) { send(GestureEvent::pitchBend(value14).onChannel(channel)); }
    /// RPN `rpn` (MSB 0) set to `value` on `channel`, then deselected (RPN null), as MPE senders do.
    void rpn(int channel, int number, int value)
    {
        cc(channel, 101, 0);
        cc(channel, 100, number);
        cc(channel, 6, value);
        cc(channel, 101, 127);
        cc(channel, 100, 127);
    }
    /// MPE Configuration Message for the lower zone: RPN 6 on the master channel 1.
    void mpe(int memberChannels) { rpn(1, 6, memberChannels); }
    void run(int samples)
    {
        for (int k = 0; k < samples; ++k)
            controller.next(in.data());
    }
    const physics::BowInput& input(int s) const { return in[static_cast<std::size_t>(s)]; }
    /// f_open / f_note x 2^(-bend / 12): the finger for `note` on string s, bent by `semitones`.
    double expectedFinger(int s, int note, double semitones) const
    {
        return open[static_cast<std::size_t>(s)] / noteFrequency(note) * std::exp2(-semitones / 12.0);
    }
};

/// The 14-bit bend that means `semitones` with a range of +-`range` semitones.
int bendValue(double semitones, double range)
{
    return static_cast<int>(std::lround(8192.0 + 8192.0 * semitones / range));
}

// Cello strings 0..3: C2 G2 D3 A3 (MIDI 36 43 50 57). C4 (60) is an A-string note, F3 (53) a D-string note.
constexpr int kAString = 3, kDString = 2;
constexpr int kC4 = 60, kF3 = 53;

TEST(MpeZone, ConfigurationMessageTurnsTheLowerZoneOnAndOff)
{
    Rig rig;
    EXPECT_FALSE(rig.controller.mpeEnabled());
    EXPECT_EQ(rig.controller.memberChannelCount(), 0);
    EXPECT_EQ(rig.controller.channels().channel(2).bendRange(), midimap::pitchBendSemitones);

    rig.mpe(15);
    EXPECT_TRUE(rig.controller.mpeEnabled());
    EXPECT_EQ(rig.controller.memberChannelCount(), 15);
    // MPE defaults: master +-2, members +-48.
    EXPECT_EQ(rig.controller.channels().channel(1).bendRange(), 2.0);
    EXPECT_EQ(rig.controller.channels().channel(2).bendRange(), 48.0);
    EXPECT_EQ(rig.controller.channels().channel(16).bendRange(), 48.0);

    rig.mpe(4); // members 2..5
    EXPECT_TRUE(rig.controller.channels().isMemberChannel(5));
    EXPECT_FALSE(rig.controller.channels().isMemberChannel(6));
    EXPECT_FALSE(rig.controller.channels().isMemberChannel(1));
    EXPECT_EQ(rig.controller.channels().channel(6).bendRange(), 2.0);

    rig.mpe(0);
    EXPECT_FALSE(rig.controller.mpeEnabled());
    EXPECT_EQ(rig.controller.channels().channel(2).bendRange(), 2.0);

    rig.rpn(2, 6, 15); // RPN 6 anywhere but the lower zone's master channel is not a lower-zone MCM
    EXPECT_FALSE(rig.controller.mpeEnabled());
}

TEST(MpeZone, ResetKeepsTheZoneAndClearsTheBend)
{
    Rig rig;
    rig.mpe(15);
    rig.bend(2, bendValue(12.0, 48.0));
    rig.controller.reset();
    EXPECT_TRUE(rig.controller.mpeEnabled());
    EXPECT_EQ(rig.controller.channels().channel(2).bendRange(), 48.0);
    EXPECT_EQ(rig.controller.channels().channel(2).bendSemitones(), 0.0);
}

TEST(MpeZone, MemberChannelBendGlidesOnlyItsOwnString)
{
    Rig rig;
    rig.mpe(15);
    rig.noteOn(2, kC4);
    rig.noteOn(3, kF3);
    ASSERT_EQ(rig.controller.note(kAString), kC4);
    ASSERT_EQ(rig.controller.channel(kAString), 2);
    ASSERT_EQ(rig.controller.note(kDString), kF3);
    rig.run(kSettle);
    EXPECT_NEAR(rig.input(kAString).fingerRatio, rig.expectedFinger(kAString, kC4, 0.0), 1e-12);

    // +12 semitones with the 48-semitone member range: 8192 + 8192 x 12 / 48.
    rig.bend(2, 8192 + 8192 * 12 / 48);
    rig.run(kSettle);
    EXPECT_NEAR(rig.input(kAString).fingerRatio, rig.expectedFinger(kAString, kC4, 12.0), 1e-12);
    EXPECT_NEAR(rig.input(kAString).fingerRatio, 0.5 * rig.expectedFinger(kAString, kC4, 0.0), 1e-12);
    EXPECT_EQ(rig.input(kDString).fingerRatio, rig.expectedFinger(kDString, kF3, 0.0));
}

TEST(MpeZone, MemberChannelPressureScalesOnlyItsStringsForce)
{
    GestureParameters p;
    p.bowForce = 1.0;
    Rig rig(physics::celloInstrument(), p);
    rig.mpe(15);
    rig.noteOn(2, kC4);
    rig.noteOn(3, kF3);
    rig.run(kLongSettle);
    rig.send(GestureEvent::channelPressure(96).onChannel(2));
    rig.run(kSettle);
    EXPECT_NEAR(rig.input(kAString).bowForce, 1.0 * midimap::controllerFactor(96), 1e-6);
    EXPECT_NEAR(rig.input(kAString).bowForce, 2.0, 1e-6);
    EXPECT_NEAR(rig.input(kDString).bowForce, 1.0, 1e-6);
}

TEST(MpeZone, MemberChannelSlideMovesOnlyItsStringsBowPosition)
{
    GestureParameters p;
    p.beta = 0.1;
    Rig rig(physics::celloInstrument(), p);
    rig.mpe(15);
    rig.noteOn(2, kC4);
    rig.noteOn(3, kF3);
    rig.run(kSettle);
    EXPECT_NEAR(rig.input(kAString).beta, 0.1, 1e-12); // CC74 starts neutral (64)
    rig.cc(2, midimap::ccSlide, 127);
    rig.run(kSettle);
    EXPECT_NEAR(rig.input(kAString).beta, 0.1 * std::exp2(63.0 / 64.0), 1e-9);
    EXPECT_NEAR(rig.input(kDString).beta, 0.1, 1e-12);
    rig.cc(2, midimap::ccSlide, 0);
    rig.run(kSettle);
    EXPECT_NEAR(rig.input(kAString).beta, 0.05, 1e-9);
}

TEST(MpeZone, MasterChannelAppliesToEveryStringOnTopOfTheMemberChannels)
{
    GestureParameters p;
    p.bowForce = 1.0;
    Rig rig(physics::celloInstrument(), p);
    rig.mpe(15);
    rig.noteOn(2, kC4);
    rig.noteOn(3, kF3);
    rig.run(kLongSettle);
    rig.bend(2, bendValue(12.0, 48.0));
    rig.bend(1, bendValue(1.0, 2.0)); // master: +1 semitone of its +-2
    rig.cc(1, midimap::ccForce, 96);  // master: force x 2
    rig.run(kSettle);
    // The bends add in semitones (their finger factors multiply).
    EXPECT_NEAR(rig.input(kAString).fingerRatio, rig.expectedFinger(kAString, kC4, 13.0), 1e-12);
    EXPECT_NEAR(rig.input(kDString).fingerRatio, rig.expectedFinger(kDString, kF3, 1.0), 1e-12);
    EXPECT_NEAR(rig.input(kAString).bowForce, 2.0, 1e-6);
    EXPECT_NEAR(rig.input(kDString).bowForce, 2.0, 1e-6);
}

TEST(MpeZone, MemberChannelKeepsItsStringWhileANoteIsDown)
{
    Rig rig;
    rig.mpe(15);
    rig.noteOn(2, 55); // G3: D string
    ASSERT_EQ(rig.controller.note(kDString), 55);
    rig.run(kSettle); // past the chord window
    // A#3 would go to the A string, but channel 2 still holds the D string: a legato finger change there.
    EXPECT_EQ(rig.controller.stringForNote(58, 3), kAString);
    EXPECT_EQ(rig.controller.stringForNote(58, 2), kDString);
    rig.noteOn(2, 58);
    EXPECT_EQ(rig.controller.note(kDString), 58);
    EXPECT_EQ(rig.controller.stroke(kAString).phase(), BowStroke::Phase::Idle);
    rig.run(kSettle);
    EXPECT_GT(rig.input(kDString).bowVelocity, 0.0); // no bow change
    EXPECT_NEAR(rig.input(kDString).fingerRatio, rig.expectedFinger(kDString, 58, 0.0), 1e-12);
    rig.noteOff(2, 55); // the first key: its note is gone from the string
    EXPECT_TRUE(rig.controller.stroke(kDString).bowing());
    rig.noteOff(2, 58);
    EXPECT_EQ(rig.controller.stroke(kDString).phase(), BowStroke::Phase::Release);
}

TEST(MpeZone, SimultaneousNotesOnTwoMemberChannelsAreADoubleStop)
{
    Rig rig;
    rig.mpe(15);
    rig.noteOn(2, 59); // B3: A string
    rig.noteOn(3, 60); // C4, also an A-string note: moves to the D string
    EXPECT_EQ(rig.controller.channel(kAString), 2);
    EXPECT_EQ(rig.controller.channel(kDString), 3);
    EXPECT_EQ(rig.controller.note(kDString), 60);
}

TEST(PitchBendRange, Rpn0SetsTheRangeOfItsChannel)
{
    Rig rig;
    rig.rpn(1, 0, 12);
    EXPECT_EQ(rig.controller.channels().channel(1).bendRange(), 12.0);
    EXPECT_EQ(rig.controller.channels().channel(2).bendRange(), 2.0);
    rig.noteOn(1, kC4);
    rig.bend(1, 8192 + 4096); // half of +-12
    rig.run(kSettle);
    EXPECT_NEAR(rig.input(kAString).fingerRatio, rig.expectedFinger(kAString, kC4, 6.0), 1e-12);

    // Data entry LSB: cents.
    rig.cc(1, 101, 0);
    rig.cc(1, 100, 0);
    rig.cc(1, 6, 1);
    rig.cc(1, 38, 50);
    EXPECT_DOUBLE_EQ(rig.controller.channels().channel(1).bendRange(), 1.5);
    // RPN null, or an NRPN selected: data entry changes nothing.
    rig.cc(1, 101, 127);
    rig.cc(1, 100, 127);
    rig.cc(1, 6, 24);
    rig.cc(1, 101, 0);
    rig.cc(1, 100, 0);
    rig.cc(1, 99, 1);
    rig.cc(1, 98, 2);
    rig.cc(1, 6, 24);
    EXPECT_DOUBLE_EQ(rig.controller.channels().channel(1).bendRange(), 1.5);
}

TEST(PitchBendRange, Rpn0OnAMemberChannelSetsTheWholeZone)
{
    Rig rig;
    rig.mpe(15);
    rig.rpn(3, 0, 24);
    EXPECT_EQ(rig.controller.channels().channel(2).bendRange(), 24.0);
    EXPECT_EQ(rig.controller.channels().channel(16).bendRange(), 24.0);
    EXPECT_EQ(rig.controller.channels().channel(1).bendRange(), 2.0);
}

TEST(Channels, SingleChannelPlayingOnChannelFiveFollowsThatChannel)
{
    GestureParameters p;
    p.bowForce = 1.0;
    Rig rig(physics::celloInstrument(), p);
    rig.noteOn(5, kC4);
    EXPECT_EQ(rig.controller.channel(kAString), 5);
    rig.run(kLongSettle);
    rig.bend(5, bendValue(1.0, 2.0));
    rig.cc(5, midimap::ccForce, 96);
    rig.run(kSettle);
    EXPECT_NEAR(rig.input(kAString).fingerRatio, rig.expectedFinger(kAString, kC4, 1.0), 1e-12);
    EXPECT_NEAR(rig.input(kAString).bowForce, 2.0, 1e-6);
    // Another channel's controllers and note-offs belong to that channel's notes.
    rig.bend(1, 16383);
    rig.cc(1, midimap::ccForce, 0);
    rig.noteOff(1, kC4);
    rig.run(kSettle);
    EXPECT_NEAR(rig.input(kAString).fingerRatio, rig.expectedFinger(kAString, kC4, 1.0), 1e-12);
    EXPECT_NEAR(rig.input(kAString).bowForce, 2.0, 1e-6);
    EXPECT_TRUE(rig.controller.stroke(kAString).bowing());
    rig.noteOff(5, kC4);
    EXPECT_EQ(rig.controller.stroke(kAString).phase(), BowStroke::Phase::Release);
}

TEST(Channels, RawMidiBytesCarryTheChannelToTheController)
{
    Rig rig;
    const auto send = [&](std::initializer_list<std::uint8_t> bytes)
    {
        const std::vector<std::uint8_t> data(bytes);
        GestureEvent e;
        ASSERT_TRUE(decodeMidi(data.data(), static_cast<int>(data.size()), 0, e));
        rig.send(e);
    };
    send({0xB0, 101, 0}); // MCM on channel 1: 15 member channels
    send({0xB0, 100, 6});
    send({0xB0, 6, 15});
    ASSERT_TRUE(rig.controller.mpeEnabled());
    send({0x91, kC4, 100});                 // note on, channel 2
    send({0xE1, 0x00, (8192 + 2048) >> 7}); // bend +12 of +-48 on channel 2 (LSB 0)
    rig.run(kSettle);
    EXPECT_EQ(rig.controller.channel(kAString), 2);
    EXPECT_NEAR(rig.input(kAString).fingerRatio, rig.expectedFinger(kAString, kC4, 12.0), 1e-12);
}

TEST(Keyswitch, SelectsTheStringForTheFollowingNotesUntilAuto)
{
    Rig rig;
    EXPECT_EQ(rig.controller.keyswitchString(), -1);
    rig.noteOn(1, midimap::keyswitchFirst + 1); // C#1: the G string
    rig.noteOff(1, midimap::keyswitchFirst + 1);
    EXPECT_EQ(rig.controller.keyswitchString(), 1); // sticky after the key is released
    EXPECT_EQ(rig.controller.stringForNote(50), 1);
    rig.noteOn(1, 50); // D3, automatically the open D string, now stopped on the G string
    EXPECT_EQ(rig.controller.note(1), 50);
    EXPECT_EQ(rig.controller.stroke(kDString).phase(), BowStroke::Phase::Idle);
    rig.run(kSettle);
    EXPECT_NEAR(rig.input(1).fingerRatio, rig.expectedFinger(1, 50, 0.0), 1e-12);

    rig.noteOn(1, midimap::keyswitchFirst + 3);
    EXPECT_EQ(rig.controller.keyswitchString(), 3);
    rig.noteOn(1, midimap::keyswitchAuto);
    EXPECT_EQ(rig.controller.keyswitchString(), -1);
    EXPECT_EQ(rig.controller.stringForNote(50), kDString);
}

TEST(Keyswitch, HostStringParameterOverridesTheKeyswitch)
{
    GestureParameters p;
    p.stringOverride = 0;
    Rig rig(physics::celloInstrument(), p);
    rig.noteOn(1, midimap::keyswitchFirst + 3);
    EXPECT_EQ(rig.controller.keyswitchString(), 3);
    EXPECT_EQ(rig.controller.stringForNote(50), 0);
    p.stringOverride = -1;
    rig.controller.setParameters(p);
    EXPECT_EQ(rig.controller.stringForNote(50), 3);
}

TEST(Keyswitch, KeyswitchNotesNeverBow)
{
    for (const auto& config : {physics::celloInstrument(), physics::violinInstrument()})
    {
        Rig rig(config);
        for (int note = midimap::keyswitchAuto; note < midimap::keyswitchFirst + 4; ++note)
        {
            EXPECT_TRUE(rig.controller.isKeyswitch(note)) << config.name << " " << note;
            EXPECT_EQ(rig.controller.stringForNote(note), -1);
            rig.noteOn(1, note, 127);
        }
        EXPECT_FALSE(rig.controller.isKeyswitch(midimap::keyswitchAuto - 1));
        EXPECT_FALSE(rig.controller.isKeyswitch(midimap::keyswitchFirst + 4));
        rig.run(kSettle);
        for (int s = 0; s < 4; ++s)
        {
            EXPECT_EQ(rig.controller.stroke(s).phase(), BowStroke::Phase::Idle) << config.name;
            EXPECT_EQ(rig.controller.note(s), -1);
            EXPECT_EQ(rig.input(s).bowForce, 0.0);
        }
    }
}

TEST(Keyswitch, KeyswitchDoesNotTouchASoundingNote)
{
    Rig rig;
    rig.noteOn(1, 50);
    rig.run(kSettle);
    rig.noteOn(1, midimap::keyswitchFirst + 2);
    rig.noteOff(1, midimap::keyswitchFirst + 2);
    rig.run(kSettle);
    EXPECT_TRUE(rig.controller.stroke(kDString).bowing());
    EXPECT_EQ(rig.controller.note(kDString), 50);
    EXPECT_GT(rig.input(kDString).bowVelocity, 0.0);
}

TEST(Keyswitch, NeverHidesAPlayableNote)
{
    // A five-string bass whose low B0 (23) reaches the keyswitch range: no keyswitches at all.
    const std::array<double, 5> open = {noteFrequency(23), noteFrequency(28), noteFrequency(33),
                                        noteFrequency(38), noteFrequency(43)};
    MidiGestureController controller;
    controller.prepare(open.data(), 5, kFs);
    for (int note = midimap::keyswitchAuto; note < midimap::keyswitchFirst + 5; ++note)
        EXPECT_FALSE(controller.isKeyswitch(note)) << note;
    controller.handleEvent(GestureEvent::noteOn(24, 100));
    EXPECT_EQ(controller.note(0), 24);
    EXPECT_EQ(controller.keyswitchString(), -1);
}

TEST(Keyswitch, ResetReturnsToTheAutomaticChoice)
{
    Rig rig;
    rig.noteOn(1, midimap::keyswitchFirst);
    rig.controller.reset();
    EXPECT_EQ(rig.controller.keyswitchString(), -1);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::player
