// Transient length in periods from the first slip to lasting Helmholtz motion ([Notes §7.3], [Galluzzo2017]
// Figs. 5-8), on onset sequences built with a known number of irregular periods.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/analysis/TransientLength.h"

using namespace rosin::analysis;

namespace ROSIN_FILE_LOCAL
{
constexpr double kP = 48000.0 / 146.8; // samples (not an integer: onsets are rounded like real ones)

struct Builder
{
    double t = 1000.0; // the first slip, samples
    std::vector<std::size_t> onsets;
    void slip() { onsets.push_back(static_cast<std::size_t>(std::lround(t))); }
    /// One period with an extra slip: intervals 0.45 P and 0.55 P (multiple slipping).
    void doubledPeriod() { slip(), t += 0.45 * kP, slip(), t += 0.55 * kP; }
    void longInterval(double periods) { slip(), t += periods * kP; }
    void helmholtz(int periods)
    {
        for (int i = 0; i < periods; ++i)
            slip(), t += kP;
        slip(); // closes the last period
    }
};

// n periods with an extra slip each, then Helmholtz: the transient is exactly n periods long.
TEST(TransientLength, IrregularPeriodsThenHelmholtzCountExactly)
{
    for (const int n : {0, 3, 7, 12})
    {
        Builder b;
        for (int i = 0; i < n; ++i)
            b.doubledPeriod();
        b.helmholtz(25);
        const auto r = measureTransient(b.onsets, kP);
        ASSERT_TRUE(r.periods.has_value()) << n;
        EXPECT_NEAR(*r.periods, n, 0.01) << n;
        EXPECT_EQ(r.firstSlip, b.onsets.front());
        EXPECT_EQ(r.failure, n == 0 ? TransientFailure::None : TransientFailure::MultipleSlipping) << n;
        EXPECT_FALSE(r.insufficientData);
        std::printf("[figure] transient with %d doubled periods: %.3f periods, failure %s\n", n, *r.periods,
                    transientFailureName(r.failure));
    }
}

// Twenty or more periods before Helmholtz motion is "not reached" ([Galluzzo2017]'s black pixel); Helmholtz
// that does not last to the end of the window does not count either.
TEST(TransientLength, CapAndLastingRun)
{
    Builder atCap, beyond;
    for (int i = 0; i < 20; ++i)
        atCap.doubledPeriod();
    atCap.helmholtz(25);
    for (int i = 0; i < 23; ++i)
        beyond.doubledPeriod();
    beyond.helmholtz(25);
    const auto rCap = measureTransient(atCap.onsets, kP);
    const auto rBeyond = measureTransient(beyond.onsets, kP);
    EXPECT_FALSE(rCap.periods.has_value());
    EXPECT_FALSE(rBeyond.periods.has_value());
    ASSERT_TRUE(rBeyond.helmholtzStart.has_value()); // found, but too late
    EXPECT_EQ(rBeyond.failure, TransientFailure::MultipleSlipping);

    // Helmholtz from the first slip, then the string stops slipping two periods before the window ends.
    Builder stops;
    stops.helmholtz(30);
    TransientOptions o;
    o.windowEnd = stops.onsets.back() + static_cast<std::size_t>(2.0 * kP);
    const auto rStops = measureTransient(stops.onsets, kP, o);
    EXPECT_FALSE(rStops.periods.has_value());
    EXPECT_EQ(rStops.failure, TransientFailure::ProlongedSticking);
    // Four Helmholtz periods are not a run; five are.
    Builder four, five;
    four.longInterval(1.5), four.helmholtz(4);
    five.longInterval(1.5), five.helmholtz(5);
    EXPECT_FALSE(measureTransient(four.onsets, kP).periods.has_value());
    EXPECT_TRUE(measureTransient(five.onsets, kP).periods.has_value());
    std::printf("[figure] transient 20 doubled periods -> %s, 23 -> %s (t_H at %.2f P), Helmholtz that stops "
                "-> %s (%s)\n",
                rCap.periods ? "reached" : "not reached", rBeyond.periods ? "reached" : "not reached",
                (static_cast<double>(*rBeyond.helmholtzStart) - static_cast<double>(rBeyond.firstSlip)) / kP,
                rStops.periods ? "reached" : "not reached", transientFailureName(rStops.failure));
}

// Long intervals before Helmholtz (prolonged sticking) vs short ones (extra slips): labelled as such, and the
// length is the time they took.
TEST(TransientLength, FailureTypeOfLongAndShortIntervals)
{
    Builder creak;
    creak.longInterval(1.6), creak.longInterval(1.4), creak.longInterval(1.8);
    creak.helmholtz(25);
    const auto rCreak = measureTransient(creak.onsets, kP);
    ASSERT_TRUE(rCreak.periods.has_value());
    EXPECT_NEAR(*rCreak.periods, 1.6 + 1.4 + 1.8, 0.01);
    EXPECT_EQ(rCreak.failure, TransientFailure::ProlongedSticking);
    EXPECT_NEAR(rCreak.longIntervalPeriods, 4.8, 0.01);
    EXPECT_EQ(rCreak.shortIntervalPeriods, 0.0);

    Builder loose;
    for (int i = 0; i < 4; ++i)
        loose.doubledPeriod();
    loose.longInterval(1.2); // one long interval among many short ones: still mostly extra slips
    loose.helmholtz(25);
    const auto rLoose = measureTransient(loose.onsets, kP);
    ASSERT_TRUE(rLoose.periods.has_value());
    EXPECT_NEAR(*rLoose.periods, 5.2, 0.01);
    EXPECT_EQ(rLoose.failure, TransientFailure::MultipleSlipping);
    std::printf("[figure] transient, long intervals: %.3f periods, %s (long %.2f P); short intervals: %.3f "
                "periods, %s (short %.2f P, long %.2f P)\n",
                *rCreak.periods, transientFailureName(rCreak.failure), rCreak.longIntervalPeriods,
                *rLoose.periods, transientFailureName(rLoose.failure), rLoose.shortIntervalPeriods,
                rLoose.longIntervalPeriods);
}

// The tolerance is a parameter and P may be the measured steady period: a string flattened by 4 % passes
// at 5 % about the nominal P but fails at 3 %, and passes again about its measured period.
TEST(TransientLength, ToleranceAndMeasuredPeriod)
{
    std::vector<std::size_t> onsets;
    for (int i = 0; i < 30; ++i)
        onsets.push_back(static_cast<std::size_t>(std::lround(500.0 + i * 1.04 * kP)));
    TransientOptions tight;
    tight.tolerance = 0.03;
    EXPECT_EQ(measureTransient(onsets, kP).periods, 0.0);
    EXPECT_FALSE(measureTransient(onsets, kP, tight).periods.has_value());
    const double Pm = steadyPeriod(onsets);
    EXPECT_NEAR(Pm / kP, 1.04, 0.005);
    EXPECT_EQ(measureTransient(onsets, Pm, tight).periods, 0.0);
    std::printf(
        "[figure] flattened 4 %%: steady period %.4f P; tolerance 5 %% about P -> 0 periods, 3 %% -> not "
        "reached, 3 %% about P_m -> 0 periods\n",
        Pm / kP);
}

// Durations: a slip longer than 2 beta P breaks a Helmholtz period when the check is asked for.
TEST(TransientLength, LongSlipsAreNotHelmholtzWhenDurationsAreChecked)
{
    std::vector<SlipEpisode> episodes;
    for (int i = 0; i < 30; ++i)
        episodes.push_back({static_cast<std::size_t>(std::lround(500.0 + i * kP)),
                            static_cast<std::size_t>(i < 4 ? 0.4 * kP : 0.1 * kP), true});
    TransientOptions o;
    o.maxSlipDuration = 2.0 * 0.1 * kP; // beta = 0.1
    const auto checked = measureTransient(episodes, kP, o);
    ASSERT_TRUE(checked.periods.has_value());
    EXPECT_NEAR(*checked.periods, 4.0, 0.01);
    EXPECT_EQ(measureTransient(episodes, kP).periods, 0.0);
}

} // namespace ROSIN_FILE_LOCAL
