// Vibrato (player/Vibrato.h) against its definition: nothing before the delay, then the set depth and rate
// within the drifts it declares, no step larger than a sinusoid of that depth and rate allows (no zipper),
// the same sequence for the same note, another for the next.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "instrument/player/Vibrato.h"

namespace rosin::player
{
namespace ROSIN_FILE_LOCAL
{

constexpr double kFs = 48000.0;

std::vector<double> run(Vibrato& v, double depth, double rate, double delay, double seconds)
{
    std::vector<double> cents;
    for (int i = 0; i < static_cast<int>(seconds * kFs); ++i)
    {
        const double factor = v.next(depth, rate, delay);
        cents.push_back(-1200.0 * std::log2(factor));
    }
    return cents;
}

TEST(Vibrato, DepthRateAndDelayAreTheSetOnes)
{
    Vibrato v;
    v.prepare(kFs, 7);
    v.startNote(1);
    const double depth = 25.0, rate = 5.5, delay = 0.3;
    const auto cents = run(v, depth, rate, delay, 4.0);
    const auto at = [&](double t) { return static_cast<std::size_t>(t * kFs); };
    for (std::size_t i = 0; i < at(delay); ++i)
        ASSERT_EQ(cents[i], 0.0) << i;
    // After the fade-in: every swing's peak within the depth drift, the crossings at the rate within its
    // drift.
    const std::size_t settled = at(delay + Vibrato::kFadeInSeconds);
    int crossings = 0;
    double peak = 0.0, lowestPeak = 1e9, highestPeak = 0.0;
    std::size_t first = 0, last = 0;
    for (std::size_t i = settled + 1; i < cents.size(); ++i)
    {
        peak = std::max(peak, std::abs(cents[i]));
        if ((cents[i - 1] < 0.0) != (cents[i] < 0.0))
        {
            if (crossings > 0)
            {
                lowestPeak = std::min(lowestPeak, peak);
                highestPeak = std::max(highestPeak, peak);
            }
            peak = 0.0;
            (crossings == 0 ? first : last) = i;
            ++crossings;
        }
    }
    const double measuredRate = 0.5 * (crossings - 1) / (static_cast<double>(last - first) / kFs);
    EXPECT_NEAR(measuredRate, rate, rate * Vibrato::kRateDrift);
    EXPECT_GT(lowestPeak, depth * (1.0 - Vibrato::kDepthDrift) * 0.99);
    EXPECT_LT(highestPeak, depth * (1.0 + Vibrato::kDepthDrift) * 1.01);
    // The largest step a sinusoid of this depth and rate takes in one sample, with the drifts' margin.
    double largest = 0.0;
    for (std::size_t i = 1; i < cents.size(); ++i)
        largest = std::max(largest, std::abs(cents[i] - cents[i - 1]));
    const double bound = 2.0 * std::numbers::pi * rate * (1.0 + Vibrato::kRateDrift) * depth *
                         (1.0 + Vibrato::kDepthDrift) / kFs;
    EXPECT_LT(largest, 1.1 * bound);
    std::printf("[ figures  ] rate %.3f Hz (set %.1f), swings %.1f-%.1f cents (set %.0f), largest step %.4f "
                "cents/sample\n",
                measuredRate, rate, lowestPeak, highestPeak, depth, largest);
}

TEST(Vibrato, TheSameNoteVibratesTheSameAndTheNextOneOtherwise)
{
    Vibrato a, b;
    a.prepare(kFs, 11);
    b.prepare(kFs, 11);
    a.startNote(3);
    b.startNote(3);
    EXPECT_EQ(run(a, 20.0, 5.5, 0.0, 1.0), run(b, 20.0, 5.5, 0.0, 1.0));
    a.startNote(3);
    b.startNote(4);
    EXPECT_NE(run(a, 20.0, 5.5, 0.0, 1.0), run(b, 20.0, 5.5, 0.0, 1.0));
}

TEST(Vibrato, AStoppedVibratoLeavesTheFingerAlone)
{
    Vibrato v;
    v.prepare(kFs, 1);
    v.startNote(1);
    run(v, 30.0, 6.0, 0.0, 1.0);
    v.stop();
    for (double c : run(v, 30.0, 6.0, 0.0, 0.1))
        ASSERT_EQ(c, 0.0);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::player
