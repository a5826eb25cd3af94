// MidiGestureController's musical mapping (MusicalMapping.cpp), at the bow inputs it writes: dynamics move
// speed, beta and force together; a slur onto another string crosses with the bow moving and the old string
// lifted; keyswitches choose the next stroke's direction and pizzicato; tremolo changes the bow at its rate;
// a plucked stopped note is damped at note-off while an open one rings; the lab mapping is untouched by it.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/physics/instrument/BowedInstrument.h"
#include "instrument/player/MidiGestureController.h"

namespace rosin::player
{
namespace ROSIN_FILE_LOCAL
{

constexpr double kFs = 48000.0;
constexpr int kC = 0, kG = 1, kD = 2, kA = 3; // the cello's strings, lowest first

struct Rig
{
    MidiGestureController controller;
    std::array<physics::BowInput, 4> in{};
    explicit Rig(GestureParameters p = musical())
    {
        std::vector<double> f;
        for (const auto& s : physics::celloInstrument().strings)
            f.push_back(s.fundamental());
        controller.prepare(f.data(), 4, kFs);
        std::array<PlayableBand, 4> bands{};
        const double z0[] = {1.31, 0.83, 0.55, 0.46};
        for (int i = 0; i < 4; ++i)
            bands[static_cast<std::size_t>(i)] = {z0[i], 0.015, 0.9, 0.2625, 1.0, 0.5, z0[i] / f[i]};
        controller.setBands(bands.data(), 4);
        controller.setParameters(p);
    }
    static GestureParameters musical()
    {
        GestureParameters p;
        p.mapping = Mapping::Musical;
        return p;
    }
    void run(double seconds)
    {
        for (int i = 0; i < static_cast<int>(seconds * kFs); ++i)
            controller.next(in.data());
    }
    void event(const GestureEvent& e) { controller.handleEvent(e); }
    const physics::BowInput& string(int s) const { return in[static_cast<std::size_t>(s)]; }
};

TEST(MusicalMapping, DynamicsMoveSpeedPositionAndForceTogether)
{
    Rig soft, loud;
    soft.event(GestureEvent::controller(11, 20));
    loud.event(GestureEvent::controller(11, 120));
    soft.event(GestureEvent::noteOn(52, 80));
    loud.event(GestureEvent::noteOn(52, 80));
    soft.run(0.5);
    loud.run(0.5);
    EXPECT_GT(std::abs(loud.string(kD).bowVelocity), 3.0 * std::abs(soft.string(kD).bowVelocity));
    EXPECT_LT(loud.string(kD).beta, soft.string(kD).beta);
    EXPECT_GT(loud.string(kD).bowForce, 3.0 * soft.string(kD).bowForce);
}

TEST(MusicalMapping, ASlurOntoAnotherStringCrossesWithTheBowMoving)
{
    Rig rig;
    rig.event(GestureEvent::noteOn(55, 80)); // G3 on the D string
    rig.run(0.5);
    const double velocity = rig.string(kD).bowVelocity;
    ASSERT_GT(std::abs(velocity), 0.01);
    rig.event(GestureEvent::noteOn(59, 80)); // B3 on the A string, overlapping: a slur
    rig.controller.next(rig.in.data());
    EXPECT_NEAR(rig.string(kA).bowVelocity, velocity, 1e-9);            // the bow arrives moving
    EXPECT_LT(rig.string(kA).bowForce, 0.01 * rig.string(kD).bowForce); // its force ramps in
    rig.run(0.03);
    EXPECT_EQ(rig.controller.stroke(kD).phase(), BowStroke::Phase::Idle); // the D string lifted in 30 ms
    EXPECT_GT(rig.string(kA).bowForce, 0.0);
    rig.event(GestureEvent::noteOff(55)); // the old key's release changes nothing
    rig.run(0.1);
    EXPECT_TRUE(rig.controller.stroke(kA).bowing());
}

TEST(MusicalMapping, KeyswitchesChooseTheStrokeDirectionAndPizzicato)
{
    Rig rig;
    rig.event(GestureEvent::noteOn(midimap::keyswitchUpBow, 100));
    rig.event(GestureEvent::noteOn(50, 80));
    rig.run(0.2);
    EXPECT_LT(rig.string(kD).bowVelocity, 0.0); // the first stroke, an up-bow
    rig.event(GestureEvent::noteOff(50));
    rig.run(0.1);
    rig.event(GestureEvent::noteOn(midimap::keyswitchPizzicato, 100));
    EXPECT_EQ(rig.controller.articulation(), Articulation::Pizzicato);
    rig.event(GestureEvent::noteOn(52, 80));
    rig.run(0.008); // the finger's place is reached through the 3 ms smoother, within the 12 ms pull
    EXPECT_EQ(rig.controller.stroke(kD).phase(), BowStroke::Phase::Pluck);
    EXPECT_NEAR(rig.string(kD).beta, 0.25 / rig.controller.fingerRatioFor(kD, 52), 0.02);
    rig.run(0.05);
    EXPECT_EQ(rig.string(kD).bowForce, 0.0); // the finger let go
    rig.event(GestureEvent::noteOn(midimap::keyswitchArco, 100));
    EXPECT_EQ(rig.controller.articulation(), Articulation::Arco);
}

TEST(MusicalMapping, AStoppedPluckIsDampedAtNoteOffAnOpenOneRings)
{
    GestureParameters p = Rig::musical();
    p.articulation = Articulation::Pizzicato;
    Rig rig(p);
    rig.event(GestureEvent::noteOn(52, 80)); // stopped E3
    rig.event(GestureEvent::noteOn(57, 80)); // open A3 (a chord: another string)
    rig.run(0.3);
    rig.event(GestureEvent::noteOff(52));
    rig.event(GestureEvent::noteOff(57));
    rig.run(0.01);
    EXPECT_EQ(rig.controller.stroke(kD).phase(), BowStroke::Phase::Damp);
    EXPECT_GT(rig.string(kD).bowForce, 0.0);
    EXPECT_EQ(rig.string(kD).bowVelocity, 0.0);
    EXPECT_EQ(rig.string(kA).bowForce, 0.0);
}

TEST(MusicalMapping, TremoloChangesTheBowAtItsRate)
{
    GestureParameters p = Rig::musical();
    p.tremoloRate = 10.0;
    Rig rig(p);
    rig.event(GestureEvent::controller(midimap::ccTremolo, 127));
    rig.event(GestureEvent::noteOn(50, 80));
    int reversals = 0;
    double last = 0.0;
    for (int i = 0; i < static_cast<int>(1.0 * kFs); ++i)
    {
        rig.controller.next(rig.in.data());
        const double v = rig.string(kD).bowVelocity;
        if (last != 0.0 && v != 0.0 && (v > 0.0) != (last > 0.0))
            ++reversals;
        if (v != 0.0)
            last = v;
    }
    EXPECT_NEAR(reversals, 10, 1);
}

TEST(MusicalMapping, TheLabMappingIgnoresTheMusicalControls)
{
    GestureParameters lab;
    Rig a(lab), b(lab);
    b.event(GestureEvent::controller(midimap::ccBowPressure, 127));
    b.event(GestureEvent::controller(midimap::ccTremolo, 127));
    for (Rig* r : {&a, &b})
        r->event(GestureEvent::noteOn(52, 80));
    for (int i = 0; i < 24000; ++i)
    {
        a.controller.next(a.in.data());
        b.controller.next(b.in.data());
        ASSERT_EQ(a.string(kD).bowForce, b.string(kD).bowForce);
        ASSERT_EQ(a.string(kD).bowVelocity, b.string(kD).bowVelocity);
    }
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::player
