// Per-sample values of BowGesture: exact constant-acceleration velocity, snapping smoother, ramps, holds.
#include <gtest/gtest.h>

#include <cmath>

#include "support/AllocationCounter.h"

#include "core/gesture/BowGesture.h"
#include "core/gesture/GestureLimits.h"

namespace rosin::gesture
{
namespace ROSIN_FILE_LOCAL
{

constexpr double kFs = 48000.0;

GestureScript oneSegment(const Segment& s)
{
    GestureScript script;
    script.segments.push_back(s);
    return script;
}

TEST(BowGesture, AccelerationSegmentGivesExactlyATimesKOverFs)
{
    Segment s;
    s.seconds = 0.5;
    s.force = Ramp::constant(1.0);
    s.acceleration = 1.56;
    BowGesture g;
    g.prepare(oneSegment(s), GestureStart{}, kFs);
    ASSERT_EQ(g.totalSamples(), 24000);
    for (std::int64_t k = 0; k < g.totalSamples(); ++k)
    {
        const auto in = g.next();
        // Bit-exact, not approximately: the first slip depends on the velocity history.
        ASSERT_EQ(in.bowVelocity, 1.56 * (static_cast<double>(k) / kFs)) << "sample " << k;
    }
}

TEST(BowGesture, AccelerationIsNotSmoothedEvenAfterASpeedStep)
{
    GestureScript script;
    Segment hold;
    hold.seconds = 0.01;
    hold.speed = Ramp::constant(0.3);
    Segment brake;
    brake.seconds = 0.1;
    brake.acceleration = -2.0;
    script.segments = {hold, brake};
    BowGesture g;
    g.prepare(script, GestureStart{}, kFs);
    for (int k = 0; k < 480; ++k)
        EXPECT_EQ(g.next().bowVelocity, 0.3); // constant target: the snapped smoother stays put
    for (int k = 0; k < 4800; ++k)
        ASSERT_EQ(g.next().bowVelocity, 0.3 + -2.0 * (static_cast<double>(k) / kFs)) << "sample " << k;
}

TEST(BowGesture, SmootherSnapsToFirstValueAndCovers99PercentWithinFiveTimeConstants)
{
    GestureScript script;
    Segment a;
    a.seconds = 0.1;
    a.force = Ramp::constant(1.0);
    a.beta = Ramp::constant(0.1);
    a.finger = Ramp::constant(1.0);
    a.speed = Ramp::constant(0.05);
    Segment b = a;
    b.force = Ramp::constant(3.0);
    b.beta = Ramp::constant(0.2);
    b.finger = Ramp::constant(0.5);
    b.speed = Ramp::constant(0.15);
    script.segments = {a, b};

    BowGesture g;
    g.prepare(script, GestureStart{}, kFs);
    const auto first = g.next();
    EXPECT_EQ(first.bowForce, 1.0); // snapped: no ramp from zero
    EXPECT_EQ(first.beta, 0.1);
    EXPECT_EQ(first.fingerRatio, 1.0);
    EXPECT_EQ(first.bowVelocity, 0.05);
    for (int k = 1; k < 4800; ++k)
        g.next();

    const double tauSamples = BowGesture::kDefaultSmoothingSeconds * kFs;
    const auto stepStart = g.next(); // first sample of segment b: one smoothing step taken
    EXPECT_GT(stepStart.bowForce, 1.0);
    EXPECT_LT(stepStart.bowForce, 1.5);
    physics::BowInput in = stepStart;
    for (int k = 1; k <= static_cast<int>(std::ceil(5.0 * tauSamples)); ++k)
        in = g.next();
    auto fractionCovered = [](double value, double from, double to) { return (value - from) / (to - from); };
    EXPECT_GE(fractionCovered(in.bowForce, 1.0, 3.0), 0.99);
    EXPECT_GE(fractionCovered(in.beta, 0.1, 0.2), 0.99);
    EXPECT_GE(fractionCovered(in.fingerRatio, 1.0, 0.5), 0.99);
    EXPECT_GE(fractionCovered(in.bowVelocity, 0.05, 0.15), 0.99);
    // ... but not already after one time constant (it is a real smoother, 63 % there).
    BowGesture again;
    again.prepare(script, GestureStart{}, kFs);
    for (int k = 0; k < 4800 + static_cast<int>(tauSamples); ++k)
        in = again.next();
    EXPECT_NEAR(fractionCovered(in.bowForce, 1.0, 3.0), 1.0 - std::exp(-1.0), 0.01);
}

TEST(BowGesture, RampsAreLinearInTimeWhenSmoothingIsOff)
{
    Segment s;
    s.seconds = 1.0;
    s.force = Ramp{0.5, 1.5};
    s.speed = Ramp{0.0, 0.2};
    s.beta = Ramp{0.05, 0.15};
    BowGesture g;
    g.prepare(oneSegment(s), GestureStart{}, 1000.0, 0.0);
    for (int k = 0; k < 1000; ++k)
    {
        const auto in = g.next();
        const double t = k / 1000.0;
        ASSERT_NEAR(in.bowForce, 0.5 + 1.0 * t, 1e-12);
        ASSERT_NEAR(in.bowVelocity, 0.2 * t, 1e-12);
        ASSERT_NEAR(in.beta, 0.05 + 0.1 * t, 1e-12);
    }
}

TEST(BowGesture, AbsentQuantitiesHoldAndRampsWithoutFromContinue)
{
    GestureScript script;
    Segment a;
    a.seconds = 0.01;
    a.force = Ramp::constant(2.0);
    a.acceleration = 1.0;
    Segment b;
    b.seconds = 0.01;
    b.force = Ramp::towards(0.0); // from 2 N, wherever a left it
    // speed absent: holds the velocity the acceleration reached
    script.segments = {a, b};
    GestureStart start;
    start.beta = 0.127;
    BowGesture g;
    g.prepare(script, start, 1000.0, 0.0);
    EXPECT_EQ(g.totalSamples(), 20);
    physics::BowInput in;
    for (int k = 0; k < 10; ++k)
        in = g.next();
    EXPECT_EQ(in.beta, 0.127); // the start's beta (the preset's) when no segment sets one
    EXPECT_EQ(in.fingerRatio, 1.0);
    in = g.next(); // first sample of b
    EXPECT_DOUBLE_EQ(in.bowForce, 2.0);
    EXPECT_DOUBLE_EQ(in.bowVelocity, 0.01); // a * 10 samples / fs: continues the straight line
    for (int k = 11; k < 20; ++k)
        in = g.next();
    EXPECT_NEAR(in.bowForce, 2.0 * (1.0 - 9.0 / 10.0), 1e-12);
    EXPECT_DOUBLE_EQ(in.bowVelocity, 0.01);
    EXPECT_TRUE(g.finished());
    const auto after = g.next(); // past the end: the final values are held
    EXPECT_NEAR(after.bowForce, 0.0, 1e-12);
    EXPECT_TRUE(g.finished());
}

TEST(BowGesture, SegmentBoundariesAreRoundedCumulatively)
{
    GestureScript script;
    Segment s;
    s.seconds = 1.0 / 3.0;
    s.speed = Ramp::constant(0.1);
    script.segments = {s, s, s};
    BowGesture g;
    g.prepare(script, GestureStart{}, 44100.0);
    EXPECT_EQ(g.totalSamples(), 44100); // no drift from per-segment rounding
}

TEST(BowGesture, ResetReplaysIdentically)
{
    Segment s;
    s.seconds = 0.05;
    s.force = Ramp{0.2, 2.0};
    s.acceleration = 3.0;
    BowGesture g;
    g.prepare(oneSegment(s), GestureStart{}, kFs);
    std::vector<double> first;
    for (int k = 0; k < 2400; ++k)
        first.push_back(g.next().bowForce);
    g.reset();
    for (int k = 0; k < 2400; ++k)
        ASSERT_EQ(g.next().bowForce, first[static_cast<std::size_t>(k)]);
}

TEST(BowGesture, NextNeverAllocates)
{
    GestureScript script;
    Segment a;
    a.seconds = 0.02;
    a.force = Ramp{0.5, 1.0};
    a.speed = Ramp{0.0, 0.1};
    Segment b;
    b.seconds = 0.02;
    b.acceleration = -1.0;
    b.finger = Ramp{1.0, 0.5};
    script.segments = {a, b};
    BowGesture g;
    g.prepare(script, GestureStart{}, kFs);
    long allocations = 0;
    double sum = 0.0;
    {
        rosin::test::AllocationCounter counter;
        for (int k = 0; k < 4000; ++k)
            sum += g.next().bowVelocity;
        g.reset();
        sum += g.next().bowForce;
        allocations = counter.count();
    }
    EXPECT_EQ(allocations, 0);
    EXPECT_TRUE(std::isfinite(sum));
}

TEST(BowGesture, PrepareRejectsInvalidScripts)
{
    Segment s;
    s.seconds = 0.1;
    s.speed = Ramp::constant(0.1);
    s.acceleration = 1.0;
    BowGesture g;
    try
    {
        g.prepare(oneSegment(s), GestureStart{}, kFs);
        FAIL() << "expected GestureError";
    }
    catch (const GestureError& e)
    {
        EXPECT_EQ(e.field(), "segments[0]");
    }
    EXPECT_THROW(g.prepare(GestureScript{}, GestureStart{}, kFs), GestureError);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::gesture
