// The musical mapping's arm (player/DynamicsPath.h) and left hand between notes (FingerGlide.h), against
// what players do (Resources/docs/playing.md): louder is faster, nearer the bridge and heavier; more bow
// pressure is more force; a slur's finger moves monotonically and lands on the note, quickly when the
// landing is hard, slowly when it is soft.
#include <gtest/gtest.h>

#include <cmath>

#include "instrument/player/DynamicsPath.h"
#include "instrument/player/FingerGlide.h"

namespace rosin::player
{
namespace ROSIN_FILE_LOCAL
{

const PlayableBand kCelloD{0.548, 0.0157, 0.9, 0.2625, 1.0, 0.5, 0.00373}; // about the engine's cello D3

TEST(DynamicsPath, LouderIsFasterNearerTheBridgeAndHeavier)
{
    const DynamicsPath path;
    MusicalBow previous = musicalBow(path, kCelloD, 0.0, 0.5, 1.0);
    for (double d = 0.1; d <= 1.0001; d += 0.1)
    {
        const MusicalBow bow = musicalBow(path, kCelloD, d, 0.5, 1.0);
        EXPECT_GT(bow.bowSpeed, previous.bowSpeed) << d;
        EXPECT_LT(bow.beta, previous.beta) << d;
        // Heavier, once above the force floor that holds the softest notes (kMusicalForceMin).
        if (previous.bowForce > kMusicalForceMin)
            EXPECT_GT(bow.bowForce, previous.bowForce) << d;
        else
            EXPECT_GE(bow.bowForce, kMusicalForceMin) << d;
        EXPECT_LT(bow.bowForce, bow.upperForce) << d;
        previous = bow;
    }
    // The path's ends are its stated speeds and positions; Helmholtz motion's level v_b / beta spans them.
    EXPECT_NEAR(musicalBow(path, kCelloD, 0.0, 0.5, 1.0).bowSpeed, path.speedPp, 1e-12);
    EXPECT_NEAR(musicalBow(path, kCelloD, 1.0, 0.5, 1.0).beta, path.betaFf, 1e-12);
    const double spanDb = 20.0 * std::log10(path.speedFf / path.speedPp * path.betaPp / path.betaFf);
    EXPECT_GT(spanDb, 30.0);
}

TEST(DynamicsPath, BowPressureGoesFromFlautandoToScratch)
{
    const DynamicsPath path;
    const double d = 0.8; // where the band lies above the force floor
    const double v = path.bowSpeed(d), beta = path.beta(d);
    const double flautando = musicalBow(path, kCelloD, d, 0.0, 1.0).bowForce;
    const double normal = musicalBow(path, kCelloD, d, 0.5, 1.0).bowForce;
    const double scratch = musicalBow(path, kCelloD, d, 1.0, 1.0).bowForce;
    EXPECT_LT(flautando, normal);
    EXPECT_LT(normal, scratch);
    EXPECT_NEAR(flautando, kCelloD.lowerEdge * kCelloD.minimumForce(v, beta), 1e-9);
    EXPECT_GT(scratch, kCelloD.upperEdge * kCelloD.maximumForce(v, beta));
}

TEST(FingerGlide, ASlurLandsMonotonicallyFastWhenHardSlowWhenSoft)
{
    EXPECT_DOUBLE_EQ(slurSeconds(120, 0.25), kFastPlacementSeconds);
    EXPECT_DOUBLE_EQ(slurSeconds(30, 0.25), 0.25);
    EXPECT_GT(slurSeconds(50, 0.25), 0.15);
    FingerGlide glide;
    glide.prepare(48000.0);
    const double from = 1.0, to = std::exp2(-3.0 / 12.0);
    glide.start(from, to, 0.2);
    double last = from;
    int samples = 0;
    while (glide.gliding())
    {
        const double x = glide.next();
        ASSERT_LE(x, last);
        last = x;
        ++samples;
    }
    EXPECT_EQ(samples, 9600);
    EXPECT_NEAR(last, to, 1e-12);
    EXPECT_EQ(glide.next(), to);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::player
