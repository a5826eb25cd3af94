// MidiGestureController: where notes are played, the exact attack ramp, bow changes, the bow lift, pedal,
// controllers and sample-accurate, allocation-free stepping.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/physics/instrument/BowedInstrument.h"
#include "instrument/player/MidiGestureController.h"
#include "instrument/player/StringChoice.h"

namespace rosin::player
{
namespace ROSIN_FILE_LOCAL
{

constexpr double kFs = 48000.0;

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
    std::array<physics::BowInput, 4> in{};
    explicit Rig(const physics::InstrumentConfig& config = physics::celloInstrument(),
                 GestureParameters p = {})
    {
        const auto f = openFrequencies(config);
        controller.prepare(f.data(), static_cast<int>(f.size()), kFs);
        controller.setParameters(p);
    }
    const physics::BowInput& step(int s)
    {
        controller.next(in.data());
        return in[static_cast<std::size_t>(s)];
    }
};

double cents(double ratio)
{
    return 1200.0 * std::log2(ratio);
}

// Nominal open-string MIDI notes: cello C2 G2 D3 A3, violin G3 D4 A4 E5.
void expectStringChoice(const physics::InstrumentConfig& config, const std::array<int, 4>& openNotes)
{
    Rig rig(config);
    for (int note = openNotes[0]; note <= openNotes[3] + 36; ++note)
    {
        int expected = 0;
        for (int s = 0; s < 4; ++s)
            if (openNotes[static_cast<std::size_t>(s)] <= note)
                expected = s;
        EXPECT_EQ(rig.controller.stringForNote(note), expected) << config.name << " note " << note;
    }
    // Below the lowest string: the lowest string, open.
    EXPECT_EQ(rig.controller.stringForNote(openNotes[0] - 3), 0);
    EXPECT_EQ(rig.controller.fingerRatioFor(0, openNotes[0] - 3), 1.0);
}

TEST(MidiGestureController, ChoosesTheHighestOpenStringAtOrBelowEveryCelloNote)
{
    expectStringChoice(physics::celloInstrument(), {36, 43, 50, 57});
}

TEST(MidiGestureController, ChoosesTheHighestOpenStringAtOrBelowEveryViolinNote)
{
    expectStringChoice(physics::violinInstrument(), {55, 62, 69, 76});
}

TEST(MidiGestureController, StringParameterOverridesTheChoice)
{
    GestureParameters p;
    p.stringOverride = 1;
    Rig rig(physics::celloInstrument(), p);
    EXPECT_EQ(rig.controller.stringForNote(69), 1);
    EXPECT_EQ(rig.controller.stringForNote(36), 1);
}

TEST(MidiGestureController, FingerRatioGivesTheEqualTemperedPitchWithinATenthOfACent)
{
    for (const auto& config : {physics::celloInstrument(), physics::violinInstrument()})
    {
        Rig rig(config);
        const auto f = openFrequencies(config);
        for (int note = 36; note <= 100; ++note)
        {
            const int s = rig.controller.stringForNote(note);
            const double ratio = rig.controller.fingerRatioFor(s, note);
            if (ratio >= 1.0 || ratio <= 0.1)
                continue; // below the string (open) or beyond the finger range
            const double sounding = f[static_cast<std::size_t>(s)] / ratio;
            EXPECT_LT(std::abs(cents(sounding / noteFrequency(note))), 0.1)
                << config.name << " note " << note;
        }
    }
}

TEST(MidiGestureController, AttackIsAnExactConstantAccelerationFromRestToTheTargetSpeed)
{
    GestureParameters p;
    p.attackAcceleration = 2.0;
    p.bowSpeed = 0.1;
    p.bowForce = 1.0;
    Rig rig(physics::celloInstrument(), p);
    rig.controller.handleEvent(GestureEvent::noteOn(50, 127)); // open D3: string 2
    const double a = 2.0 * midimap::accelerationScale(127);
    ASSERT_EQ(a, 2.0);
    const int rampSamples = static_cast<int>(std::ceil(0.1 / a * kFs));
    for (int k = 0; k < rampSamples; ++k)
    {
        const auto& in = rig.step(2);
        ASSERT_EQ(in.bowVelocity, a * (static_cast<double>(k) / kFs)) << "sample " << k;
        ASSERT_EQ(in.fingerRatio, rig.controller.fingerRatioFor(2, 50)); // snapped, no glide into the note
        ASSERT_DOUBLE_EQ(in.bowForce, 1.0 * midimap::attackForceScale(127)) << "sample " << k;
    }
    EXPECT_DOUBLE_EQ(rig.step(2).bowVelocity, 0.1); // reached and held
    EXPECT_EQ(rig.in[0].bowForce, 0.0);             // other strings stay at rest
    EXPECT_EQ(rig.in[0].bowVelocity, 0.0);
}

TEST(MidiGestureController, VelocityScalesAccelerationAndInitialForce)
{
    GestureParameters p;
    p.attackAcceleration = 4.0;
    Rig rig(physics::celloInstrument(), p);
    rig.controller.handleEvent(GestureEvent::noteOn(57, 40));
    rig.step(3);
    const auto& in = rig.step(3);
    EXPECT_EQ(in.bowVelocity, 4.0 * midimap::accelerationScale(40) * (1.0 / kFs));
    EXPECT_DOUBLE_EQ(in.bowForce, p.bowForce * midimap::attackForceScale(40));
    EXPECT_LT(midimap::accelerationScale(40), midimap::accelerationScale(100));
    EXPECT_LT(midimap::attackForceScale(40), midimap::attackForceScale(100));
}

TEST(MidiGestureController, RepeatedNoteIsABowChangeThatReversesTheVelocity)
{
    GestureParameters p;
    p.attackAcceleration = 5.0;
    p.bowSpeed = 0.2;
    Rig rig(physics::celloInstrument(), p);
    rig.controller.handleEvent(GestureEvent::noteOn(50, 127));
    for (int k = 0; k < 4800; ++k)
        rig.step(2);
    const double v0 = rig.in[2].bowVelocity;
    ASSERT_DOUBLE_EQ(v0, 0.2);
    rig.controller.handleEvent(GestureEvent::noteOn(50, 127));
    for (int k = 0; k < 4800; ++k)
    {
        const auto& in = rig.step(2);
        const double expected = std::max(-0.2, v0 - 5.0 * (static_cast<double>(k) / kFs));
        ASSERT_NEAR(in.bowVelocity, expected, 1e-15) << "sample " << k;
        ASSERT_GT(in.bowForce, 0.0); // the bow stays on the string through the change
    }
    EXPECT_DOUBLE_EQ(rig.in[2].bowVelocity, -0.2);
    EXPECT_EQ(rig.controller.stroke(2).direction(), -1.0);
}

TEST(MidiGestureController, NoteOffAndNoteOnAtTheSameSampleIsABowChange)
{
    GestureParameters p;
    p.attackAcceleration = 5.0;
    Rig rig(physics::celloInstrument(), p);
    rig.controller.handleEvent(GestureEvent::noteOn(57, 127));
    for (int k = 0; k < 4800; ++k)
        rig.step(3);
    rig.controller.handleEvent(GestureEvent::noteOff(57));
    rig.controller.handleEvent(GestureEvent::noteOn(57, 127));
    EXPECT_EQ(rig.controller.stroke(3).phase(), BowStroke::Phase::Attack);
    EXPECT_EQ(rig.controller.stroke(3).direction(), -1.0);
    for (int k = 0; k < 9600; ++k)
        rig.step(3);
    EXPECT_DOUBLE_EQ(rig.in[3].bowVelocity, -p.bowSpeed);
}

TEST(MidiGestureController, StrokesFromRestAlternateDirection)
{
    Rig rig;
    for (int stroke = 0; stroke < 3; ++stroke)
    {
        rig.controller.handleEvent(GestureEvent::noteOn(57, 100));
        for (int k = 0; k < 4800; ++k)
            rig.step(3);
        EXPECT_EQ(rig.in[3].bowVelocity > 0.0, stroke % 2 == 0) << "stroke " << stroke;
        rig.controller.handleEvent(GestureEvent::noteOff(57));
        for (int k = 0; k < 4800; ++k)
            rig.step(3);
    }
}

TEST(MidiGestureController, AnotherNoteOnABowingStringIsAFingerChangeWithoutReversal)
{
    Rig rig;
    rig.controller.handleEvent(GestureEvent::noteOn(50, 100)); // D3 open
    for (int k = 0; k < 4800; ++k)
        rig.step(2);
    // F3, on the D string too, while D3 is still held: later than the chord window, so a legato finger
    // change.
    rig.controller.handleEvent(GestureEvent::noteOn(53, 100));
    EXPECT_EQ(rig.controller.note(2), 53);
    for (int k = 0; k < 4800; ++k)
        rig.step(2);
    EXPECT_GT(rig.in[2].bowVelocity, 0.0);
    EXPECT_NEAR(rig.in[2].fingerRatio, rig.controller.fingerRatioFor(2, 53), 1e-6);
}

TEST(MidiGestureController, NoteOffLiftsTheBowToExactlyZeroForceIn20Ms)
{
    Rig rig;
    rig.controller.handleEvent(GestureEvent::noteOn(43, 100));
    for (int k = 0; k < 9600; ++k)
        rig.step(1);
    const double f0 = rig.in[1].bowForce;
    ASSERT_GT(f0, 0.5);
    rig.controller.handleEvent(GestureEvent::noteOff(43));
    double previous = f0;
    const int releaseSamples = static_cast<int>(0.02 * kFs);
    for (int k = 0; k < releaseSamples; ++k)
    {
        const auto& in = rig.step(1);
        ASSERT_LE(in.bowForce, previous) << "sample " << k;
        previous = in.bowForce;
    }
    EXPECT_EQ(rig.step(1).bowForce, 0.0);
    EXPECT_EQ(rig.in[1].bowVelocity, 0.0);
    EXPECT_EQ(rig.controller.stroke(1).phase(), BowStroke::Phase::Idle);
}

TEST(MidiGestureController, SustainPedalKeepsBowingUntilReleased)
{
    Rig rig;
    rig.controller.handleEvent(GestureEvent::controller(64, 127));
    rig.controller.handleEvent(GestureEvent::noteOn(57, 100));
    for (int k = 0; k < 4800; ++k)
        rig.step(3);
    rig.controller.handleEvent(GestureEvent::noteOff(57));
    for (int k = 0; k < 4800; ++k)
        rig.step(3);
    EXPECT_TRUE(rig.controller.stroke(3).bowing());
    rig.controller.handleEvent(GestureEvent::controller(64, 0));
    for (int k = 0; k < 1200; ++k)
        rig.step(3);
    EXPECT_EQ(rig.in[3].bowForce, 0.0);
}

TEST(MidiGestureController, DoubleStopOnTheSameStringMovesToTheNextLowerString)
{
    Rig rig;
    // Notes within the chord window form a chord: B3 on the A string, C4 (also an A-string note) moves down.
    rig.controller.handleEvent(GestureEvent::noteOn(59, 100));
    EXPECT_EQ(rig.controller.stringForNote(60), 2); // C4 goes to the D string
    rig.controller.handleEvent(GestureEvent::noteOn(60, 100));
    rig.step(0);
    EXPECT_TRUE(rig.controller.stroke(2).bowing());
    EXPECT_TRUE(rig.controller.stroke(3).bowing());
}

TEST(MidiGestureController, ControllersAndPressureScaleTheParameters)
{
    GestureParameters p;
    p.bowForce = 1.0;
    p.bowSpeed = 0.1;
    p.beta = 0.1;
    Rig rig(physics::celloInstrument(), p);
    rig.controller.handleEvent(GestureEvent::noteOn(50, 64));
    for (int k = 0; k < 48000; ++k)
        rig.step(2);
    EXPECT_NEAR(rig.in[2].bowForce, 1.0, 1e-9);
    rig.controller.handleEvent(GestureEvent::controller(1, 96));    // x2 force
    rig.controller.handleEvent(GestureEvent::controller(11, 32));   // x0.5 speed
    rig.controller.handleEvent(GestureEvent::controller(21, 127));  // x~2 beta
    rig.controller.handleEvent(GestureEvent::polyPressure(50, 32)); // x0.5 force
    for (int k = 0; k < 4800; ++k)
        rig.step(2);
    EXPECT_NEAR(rig.in[2].bowForce, 1.0, 1e-6);
    EXPECT_NEAR(rig.in[2].bowVelocity, 0.05, 1e-6);
    EXPECT_NEAR(rig.in[2].beta, 0.1 * midimap::betaControllerFactor(127), 1e-6);
    rig.controller.handleEvent(GestureEvent::pitchBend(16383)); // up ~2 semitones
    for (int k = 0; k < 4800; ++k)
        rig.step(2);
    const double bent = rig.controller.fingerRatioFor(2, 50) / rig.in[2].fingerRatio;
    EXPECT_NEAR(cents(bent), 200.0 * 8191.0 / 8192.0, 1e-3);
}

// Each string is bowed with its share of the bow force, controllers on top; a share that is not positive
// leaves every string at the force as set, and a new prepare() forgets the shares.
TEST(MidiGestureController, EachStringGetsItsShareOfTheBowForce)
{
    GestureParameters p;
    p.bowForce = 1.0;
    Rig rig(physics::celloInstrument(), p);
    const std::array<double, 4> shares{1.0, 0.63, 0.42, 0.35};
    rig.controller.setForceShares(shares.data(), 4);
    rig.controller.handleEvent(GestureEvent::noteOn(36, 64));
    rig.controller.handleEvent(GestureEvent::noteOn(57, 64));
    for (int k = 0; k < 48000; ++k)
        rig.step(0);
    EXPECT_NEAR(rig.in[0].bowForce, 1.0, 1e-9);
    EXPECT_NEAR(rig.in[3].bowForce, 0.35, 1e-9);
    rig.controller.handleEvent(GestureEvent::controller(1, 96)); // x2 force
    for (int k = 0; k < 4800; ++k)
        rig.step(0);
    EXPECT_NEAR(rig.in[3].bowForce, 0.7, 1e-6);
    const std::array<double, 4> broken{1.0, 0.5, -1.0, 0.5};
    rig.controller.setForceShares(broken.data(), 4);
    EXPECT_EQ(rig.controller.forceShare(1), 1.0);
    rig.controller.setForceShares(shares.data(), 4);
    const auto f = openFrequencies(physics::celloInstrument());
    rig.controller.prepare(f.data(), 4, kFs);
    EXPECT_EQ(rig.controller.forceShare(3), 1.0);
}

TEST(MidiGestureController, OutputDoesNotDependOnHowSamplesAreGrouped)
{
    // Events handled just before their sample: the same event list gives the same inputs whatever the block.
    const std::vector<GestureEvent> events = {
        GestureEvent::noteOn(50, 90, 10), GestureEvent::controller(1, 80, 700),
        GestureEvent::noteOn(50, 90, 3000), GestureEvent::noteOff(50, 6000)};
    std::vector<double> reference;
    for (int block : {1, 7, 512})
    {
        Rig rig;
        std::vector<double> out;
        std::size_t next = 0;
        for (int start = 0; start < 8000; start += block)
            for (int k = start; k < std::min(start + block, 8000); ++k)
            {
                while (next < events.size() && events[next].sampleOffset <= k)
                    rig.controller.handleEvent(events[next++]);
                out.push_back(rig.step(2).bowVelocity);
            }
        if (reference.empty())
            reference = out;
        else
            EXPECT_EQ(out, reference) << "block " << block;
    }
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::player
