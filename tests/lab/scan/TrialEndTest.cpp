// Where a Guettler trial ends (TrialEnd.h), on hand-made slip sequences with a known answer: full flybacks
// (3 samples at v_b / beta) at chosen onsets, period P = 300 samples, first flyback t1 = 1000, 24 000
// samples. The window rule ends 2 x 20 x 1.1 P after t1; the decided rule also ends once no Helmholtz run can
// start within the cap for any period the analysis may use (within 10 % of P), i.e. at the first full flyback
// at or after t1 + 22 P that closes an interval outside (0.855 P, 1.155 P), or at t1 + 22 P when the flybacks
// have stopped.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "lab/scan/TrialEnd.h"

using namespace rosin;
using namespace rosin::scan;

namespace ROSIN_FILE_LOCAL
{
constexpr double kP = 300.0, kBeta = 0.1, kVb = 0.2;
constexpr std::size_t kT1 = 1000, kTrial = 24000;
const std::size_t kWindowEnd = kT1 + 13200 + 1; // ceil(2 x 20 x 1.1 x P) + 1 samples after t1

// Onsets from t1 on: `count` intervals of `interval` P, then (optionally) more of another interval.
std::vector<std::size_t> onsets(double interval, int count, double then = 0.0, int thenCount = 0)
{
    std::vector<std::size_t> o{kT1};
    for (int i = 0; i < count; ++i)
        o.push_back(o.back() + static_cast<std::size_t>(interval * kP));
    for (int i = 0; i < thenCount; ++i)
        o.push_back(o.back() + static_cast<std::size_t>(then * kP));
    return o;
}

// The number of samples after which the trial ends.
std::size_t endOf(GuettlerTrialEnd rule, const std::vector<std::size_t>& flybacks)
{
    TrialEnd end(rule, kBeta, kP, kTrial);
    std::size_t next = 0;
    for (std::size_t k = 0; k < kTrial; ++k)
    {
        while (next < flybacks.size() && flybacks[next] + 3 <= k)
            ++next;
        physics::VoiceSample s;
        s.bowVelocity = kVb;
        s.sticking = !(next < flybacks.size() && k >= flybacks[next]);
        s.bowPointVelocity = s.sticking ? kVb : kVb - kVb / kBeta;
        if (end.add(s))
            return k + 1;
    }
    return kTrial + 1; // never said
}

TEST(TrialEnd, WholeTrialsRunToTheirLength)
{
    EXPECT_EQ(endOf(GuettlerTrialEnd::Whole, onsets(0.5, 60)), kTrial);
}

TEST(TrialEnd, HelmholtzMotionRunsItsWholeWindowWithEitherRule)
{
    EXPECT_EQ(endOf(GuettlerTrialEnd::AfterWindow, onsets(1.0, 70)), kWindowEnd);
    EXPECT_EQ(endOf(GuettlerTrialEnd::WhenDecided, onsets(1.0, 70)), kWindowEnd);
    // Flattened by 8 %: the analysis may measure against that period, so nothing is decided early.
    EXPECT_EQ(endOf(GuettlerTrialEnd::WhenDecided, onsets(1.08, 70)), kWindowEnd);
    // Helmholtz motion from 19.5 P on (after double slipping) is reached just within the cap.
    EXPECT_EQ(endOf(GuettlerTrialEnd::WhenDecided, onsets(0.5, 39, 1.0, 40)), kWindowEnd);
}

TEST(TrialEnd, DoubleSlippingPastTheCapEndsAtTheFirstIntervalThatDecidesIt)
{
    // Onsets every 150 samples; the first at or after t1 + 22 P = t1 + 6600 is the 44th.
    EXPECT_EQ(endOf(GuettlerTrialEnd::WhenDecided, onsets(0.5, 100)), kT1 + 6600 + 1);
    EXPECT_EQ(endOf(GuettlerTrialEnd::AfterWindow, onsets(0.5, 100)), kWindowEnd);
}

TEST(TrialEnd, StoppedFlybacksEndTheTrialAtTheCapsLatestReach)
{
    // Ten periods of Helmholtz motion, then no more flybacks (the string sticks: "creak").
    EXPECT_EQ(endOf(GuettlerTrialEnd::WhenDecided, onsets(1.0, 10)), kT1 + 6600);
    // Prolonged periods of 1.3 P past the cap: decided by the first one closing after t1 + 22 P.
    const auto slow = onsets(1.3, 30);
    std::size_t first = 0;
    for (const std::size_t o : slow)
        if (first == 0 && o >= kT1 + 6600)
            first = o;
    // The gap rule may see the interval under way first: 1.155 P after the onset before it, and not before
    // t1 + 22 P.
    const std::size_t gapSeen =
        std::max<std::size_t>(first - static_cast<std::size_t>(1.3 * kP) + 347, // > 346.5
                              kT1 + 6600);
    EXPECT_EQ(endOf(GuettlerTrialEnd::WhenDecided, slow), std::min(first + 1, gapSeen));
}

} // namespace ROSIN_FILE_LOCAL
