// The "steady:" and "guettler:" command-line gestures, and the shared range table.
#include <gtest/gtest.h>

#include "core/gesture/BowGesture.h"
#include "core/gesture/BuiltinGestures.h"
#include "core/gesture/GestureLimits.h"

namespace rosin::gesture
{
namespace ROSIN_FILE_LOCAL
{

TEST(BuiltinGestures, SteadyDefaults)
{
    const auto script = parseBuiltinGesture("steady");
    ASSERT_EQ(script.segments.size(), 1u);
    const Segment& s = script.segments[0];
    EXPECT_EQ(s.seconds, 1.0);
    EXPECT_EQ(s.speed->to, 0.05);
    EXPECT_EQ(s.force->to, 1.0);
    EXPECT_EQ(s.beta->to, 0.1);
    EXPECT_EQ(s.finger->to, 1.0);
    EXPECT_FALSE(s.acceleration.has_value());
}

TEST(BuiltinGestures, GuettlerDefaults)
{
    const auto script = parseBuiltinGesture("guettler");
    const Segment& s = script.segments[0];
    EXPECT_EQ(s.seconds, 0.5);
    EXPECT_EQ(*s.acceleration, 1.56);
    EXPECT_EQ(s.force->to, 1.0);
    EXPECT_EQ(s.beta->to, 0.0899);
    EXPECT_FALSE(s.speed.has_value());
}

TEST(BuiltinGestures, OverridesInAnyOrder)
{
    const auto script =
        parseBuiltinGesture("guettler:force=0.84,seconds=0.25,acceleration=-2,beta=0.2,finger=0.5");
    const Segment& s = script.segments[0];
    EXPECT_EQ(s.force->to, 0.84);
    EXPECT_EQ(s.seconds, 0.25);
    EXPECT_EQ(*s.acceleration, -2.0);
    EXPECT_EQ(s.beta->to, 0.2);
    EXPECT_EQ(s.finger->to, 0.5);
    EXPECT_EQ(parseBuiltinGesture("steady:").segments[0].speed->to, 0.05);
}

TEST(BuiltinGestures, GuettlerStartsFromRestWithExactAcceleration)
{
    BowGesture g;
    g.prepare(parseBuiltinGesture("guettler"), GestureStart{}, 44100.0);
    EXPECT_EQ(g.totalSamples(), 22050);
    EXPECT_EQ(g.next().bowVelocity, 0.0);
    EXPECT_EQ(g.next().bowVelocity, 1.56 * (1.0 / 44100.0));
}

TEST(BuiltinGestures, RecognisesOnlyItsNames)
{
    EXPECT_TRUE(isBuiltinGestureSpec("steady"));
    EXPECT_TRUE(isBuiltinGestureSpec("guettler:force=1"));
    EXPECT_FALSE(isBuiltinGestureSpec("steadyx"));
    EXPECT_FALSE(isBuiltinGestureSpec("gestures/steady.json"));
}

struct BadSpec
{
    const char* spec;
    const char* field;
    const char* expected; // a fragment of the expectation
};

class BuiltinGestureErrors : public ::testing::TestWithParam<BadSpec>
{
};

TEST_P(BuiltinGestureErrors, NameTheKeyAndTheExpectation)
{
    const BadSpec& bad = GetParam();
    try
    {
        parseBuiltinGesture(bad.spec);
        FAIL() << bad.spec << " was accepted";
    }
    catch (const GestureError& e)
    {
        EXPECT_EQ(e.field(), bad.field) << e.what();
        EXPECT_NE(e.expected().find(bad.expected), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("field \"" + std::string(bad.field) + "\""), std::string::npos);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Ranges, BuiltinGestureErrors,
    ::testing::Values(
        BadSpec{"steady:beta=0.009", "beta", "0.01..0.5"}, BadSpec{"steady:beta=0.51", "beta", "0.01..0.5"},
        BadSpec{"steady:force=-0.1", "force", "0..20"}, BadSpec{"steady:force=20.5", "force", "0..20"},
        BadSpec{"steady:speed=5.01", "speed", "-5..5"}, BadSpec{"steady:speed=-6", "speed", "-5..5"},
        BadSpec{"guettler:acceleration=51", "acceleration", "-50..50"},
        BadSpec{"guettler:acceleration=20", "acceleration", "within -5..5 m/s"},
        BadSpec{"steady:finger=0.05", "finger", "0.1..1"}, BadSpec{"steady:finger=1.2", "finger", "0.1..1"},
        BadSpec{"steady:seconds=0", "seconds", "> 0 and <= 600"},
        BadSpec{"steady:seconds=601", "seconds", "> 0 and <= 600"},
        BadSpec{"steady:seconds=nan", "seconds", "> 0"}, BadSpec{"steady:beta=abc", "beta", "a number"},
        BadSpec{"steady:beta=", "beta", "a number"}, BadSpec{"steady:beta", "beta", "key=value"},
        BadSpec{"steady:acceleration=1", "acceleration", "steady keys"},
        BadSpec{"guettler:speed=1", "speed", "guettler keys"}));

TEST(GestureLimits, BoundariesAreInclusiveExceptSecondsMinimum)
{
    EXPECT_TRUE(limits::beta.contains(0.01));
    EXPECT_TRUE(limits::beta.contains(0.5));
    EXPECT_TRUE(limits::force.contains(0.0));
    EXPECT_TRUE(limits::force.contains(20.0));
    EXPECT_TRUE(limits::speed.contains(-5.0));
    EXPECT_TRUE(limits::acceleration.contains(50.0));
    EXPECT_TRUE(limits::finger.contains(0.1));
    EXPECT_TRUE(limits::seconds.contains(600.0));
    EXPECT_FALSE(limits::seconds.contains(0.0));
    EXPECT_FALSE(limits::force.contains(std::numeric_limits<double>::infinity()));
    EXPECT_FALSE(limits::beta.contains(std::numeric_limits<double>::quiet_NaN()));
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::gesture
