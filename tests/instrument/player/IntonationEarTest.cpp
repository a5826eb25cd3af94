// IntonationEar in closed loop with a synthetic string whose Helmholtz period is off the nominal
// f_open / finger by a known factor (flattening or stiffness sharpening): the ear must bring the sounding
// period to the nominal one, and must leave the finger alone where there is no Helmholtz motion to hear.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "instrument/player/IntonationEar.h"

namespace rosin::player
{
namespace ROSIN_FILE_LOCAL
{

constexpr double kFs = 48000.0;
constexpr double kOpen = 146.83; // cello D3
constexpr double kBow = 0.1;     // m/s

/// A string that sticks, then flies back for 10 % of its period; its period is mistune x fs finger / f_open
/// for the finger the ear plays. Returns the last period's error in cents against the nominal note.
struct SyntheticString
{
    double mistune = 1.0; // > 1: flat
    double phase = 0.0;   // periods
    int slipsPerPeriod = 1;

    /// One sample: advances by the period the given finger gives; returns sticking, writes v.
    bool step(double finger, double& v)
    {
        const double period = mistune * kFs * finger / kOpen;
        phase += 1.0 / period;
        phase -= std::floor(phase);
        const double sub = phase * slipsPerPeriod;
        const bool slipping = sub - std::floor(sub) < 0.1;
        v = slipping ? -9.0 * kBow : kBow;
        return !slipping;
    }
};

double run(IntonationEar& ear, SyntheticString& s, double nominalFinger, double seconds)
{
    double finger = nominalFinger;
    for (int i = 0; i < static_cast<int>(seconds * kFs); ++i)
    {
        finger = ear.finger(nominalFinger);
        double v = 0.0;
        const bool sticking = s.step(finger, v);
        ear.listen(sticking, v, kBow);
    }
    // Sounding pitch against the note: f = f_open / (mistune finger), nominal f_open / nominalFinger.
    return 1200.0 * std::log2(nominalFinger / (s.mistune * finger));
}

TEST(IntonationEar, CorrectsAFlatStringToTheNominalPitch)
{
    for (const double cents : {-12.0, -5.0, 4.0, 10.0})
    {
        IntonationEar ear;
        ear.prepare(kOpen, kFs);
        SyntheticString s;
        s.mistune = std::exp2(-cents / 1200.0); // cents < 0: period longer than nominal
        const double before = 1200.0 * std::log2(1.0 / s.mistune);
        const double after = run(ear, s, 0.75, 0.8);
        std::printf("[figure] ear: string %+.1f cents off -> %+.3f cents after 0.8 s (%d windows, correction "
                    "%+.2f cents)\n",
                    before, after, ear.windowsMeasured(), ear.correctionCents());
        EXPECT_NEAR(before, cents, 1e-9);
        // Integer-sample slip onsets over a 60 ms window: about 1/2880 of a period, 0.6 cents.
        EXPECT_LT(std::abs(after), 1.0);
        EXPECT_NEAR(ear.correctionCents(), -cents, 1.0);
    }
}

TEST(IntonationEar, DisabledEarPlaysTheNominalFinger)
{
    IntonationEar ear;
    ear.prepare(kOpen, kFs);
    ear.setEnabled(false);
    SyntheticString s;
    s.mistune = std::exp2(8.0 / 1200.0);
    const double after = run(ear, s, 0.6, 0.5);
    EXPECT_NEAR(after, -8.0, 1e-9);
    EXPECT_DOUBLE_EQ(ear.finger(0.6), 0.6);
    EXPECT_GT(ear.windowsMeasured(), 0); // it still listens
}

TEST(IntonationEar, HearsThePitchOfDoubleSlipping)
{
    // Two flybacks per period: still periodic, still heard at the note's pitch.
    IntonationEar ear;
    ear.prepare(kOpen, kFs);
    SyntheticString s;
    s.slipsPerPeriod = 2;
    s.mistune = std::exp2(7.0 / 1200.0);
    const double after = run(ear, s, 0.8, 0.8);
    EXPECT_LT(std::abs(after), 1.0);
    EXPECT_NEAR(ear.correctionCents(), 7.0, 1.0);
}

TEST(IntonationEar, DoesNotCorrectAperiodicMotionOrOpenStrings)
{
    IntonationEar ear;
    ear.prepare(kOpen, kFs);
    // Flybacks at pseudo-random intervals of 0.3..0.7 nominal periods: no partner one period back.
    const double period = kFs * 0.8 / kOpen;
    std::uint32_t state = 12345u;
    double next = 0.0;
    for (int i = 0; i < 48000; ++i)
    {
        ear.finger(0.8);
        const bool slip = i >= next && i < next + 5;
        if (i >= next + 5)
        {
            state = state * 1664525u + 1013904223u;
            next = i + period * (0.3 + 0.4 * (state >> 8) / 16777216.0);
        }
        ear.listen(!slip, slip ? -0.9 : kBow, kBow);
    }
    EXPECT_EQ(ear.windowsMeasured(), 0);
    EXPECT_DOUBLE_EQ(ear.correctionCents(), 0.0);
    // Sticking throughout: nothing to hear.
    for (int i = 0; i < 24000; ++i)
        ear.listen(true, kBow, kBow);
    EXPECT_DOUBLE_EQ(ear.correctionCents(), 0.0);
    // An open string plays open, however flat it sounds.
    SyntheticString open;
    open.mistune = std::exp2(10.0 / 1200.0);
    run(ear, open, 1.0, 0.5);
    EXPECT_DOUBLE_EQ(ear.finger(1.0), 1.0);
    EXPECT_DOUBLE_EQ(ear.correctionCents(), 0.0);
}

TEST(IntonationEar, HoldsItsCorrectionDuringVibrato)
{
    IntonationEar ear;
    ear.prepare(kOpen, kFs);
    SyntheticString s;
    s.mistune = std::exp2(6.0 / 1200.0);
    run(ear, s, 0.8, 0.6);
    const double learnt = ear.correctionCents();
    const int windows = ear.windowsMeasured();
    // 6 Hz vibrato of +-20 cents: the nominal finger never holds still for a window.
    double v = 0.0;
    for (int i = 0; i < 24000; ++i)
    {
        const double nominal = 0.8 * std::exp2(20.0 / 1200.0 * std::sin(2.0 * M_PI * 6.0 * i / kFs));
        const bool sticking = s.step(ear.finger(nominal), v);
        ear.listen(sticking, v, kBow);
    }
    EXPECT_EQ(ear.windowsMeasured(), windows);
    EXPECT_DOUBLE_EQ(ear.correctionCents(), learnt);
}

TEST(IntonationEar, CorrectionIsBounded)
{
    IntonationEar ear;
    ear.prepare(kOpen, kFs);
    SyntheticString s;
    s.mistune = std::exp2(150.0 / 1200.0); // far flatter than any Helmholtz flattening
    run(ear, s, 0.7, 2.0);
    EXPECT_LE(std::abs(ear.correctionCents()), IntonationEar::kMaxCents);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::player
