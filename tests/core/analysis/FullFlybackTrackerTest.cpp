// The online full-flyback tracker against the offline analysis it stands in for: after every sample,
// onsets() must equal onsetsOf(fullFlybacksOnly(slipEpisodesFromVoice(the samples so far))). Checked on a
// simulated Guettler attack (cello D3 on the body, classical curve: double slipping, then Helmholtz motion)
// and on a hand-made sequence with the awkward cases: sliding at sample 0, a partial slip, a reversal that
// is too slow to count, and a flyback that qualifies only several samples after its onset.
#include <gtest/gtest.h>

#include <memory>

#include "core/analysis/FullFlybackTracker.h"
#include "core/analysis/SlipOnsets.h"
#include "core/physics/friction/CurveFrictionLaw.h"
#include "support/Runs.h"

using namespace rosin;
using namespace rosin::analysis;

namespace ROSIN_FILE_LOCAL
{
constexpr double kShare = 0.25;

// Compares at every sample (offline on each prefix: quadratic, so keep the sequence short).
void expectSameAsOfflineAtEverySample(const std::vector<physics::VoiceSample>& samples, double beta,
                                      std::size_t stride)
{
    FullFlybackTracker tracker(beta, kShare);
    std::vector<physics::VoiceSample> prefix;
    for (std::size_t k = 0; k < samples.size(); ++k)
    {
        tracker.add(samples[k]);
        prefix.push_back(samples[k]);
        if (k % stride != 0 && k + 1 != samples.size())
            continue;
        const auto offline = onsetsOf(fullFlybacksOnly(slipEpisodesFromVoice(prefix), beta, kShare));
        ASSERT_EQ(tracker.onsets(), offline) << "after sample " << k;
    }
    EXPECT_EQ(tracker.samples(), samples.size());
}

physics::VoiceSample sample(bool sticking, double bowVelocity, double slip)
{
    physics::VoiceSample s;
    s.sticking = sticking;
    s.bowVelocity = bowVelocity;
    s.bowPointVelocity = bowVelocity - slip;
    return s;
}

TEST(FullFlybackTracker, FollowsTheOfflineAnalysisOfASimulatedAttack)
{
    physics::VoiceConfig cfg;
    cfg.string = physics::stringFromCatalogue("cello-D3");
    cfg.body = physics::celloBody();
    const double beta = 0.0899;
    auto law = std::make_unique<physics::ClassicalFrictionLaw>(physics::ClassicalCurve{}, "classical");
    const auto trace = rosin::test::bowAccelerating(cfg, std::move(law), 48000.0, 1.0, 1.0, beta, 0.15);
    const auto all = onsetsOf(fullFlybacksOnly(slipEpisodesFromVoice(trace.samples), beta, kShare));
    ASSERT_GT(all.size(), 5u); // the attack slips, so the comparison sees onsets come and qualify
    expectSameAsOfflineAtEverySample(trace.samples, beta, 7);
}

TEST(FullFlybackTracker, HandlesEdgeCasesLikeTheOfflineAnalysis)
{
    const double beta = 0.1, vb = 0.2, full = vb / beta; // the ideal flyback speed relative to the bow
    std::vector<physics::VoiceSample> s;
    auto add = [&](bool sticking, double slip, int n)
    {
        for (int i = 0; i < n; ++i)
            s.push_back(sample(sticking, vb, slip));
    };
    add(false, full, 3);       // under way at sample 0: not an onset
    add(true, 0.0, 5);         //
    add(false, 0.5 * vb, 4);   // partial slip: the string lags the bow without reversing
    add(true, 0.0, 5);         //
    add(false, 1.5 * vb, 4);   // a reversal, but at 0.15 of v_b / beta: too slow to count
    add(true, 0.0, 5);         //
    add(false, 1.2 * vb, 3);   // from sample 26: starts as a slow reversal,
    add(false, 0.9 * full, 3); // becomes a full flyback three samples in
    add(true, 0.0, 5);
    add(false, full, 2); // and one at the very end (sample 37)
    FullFlybackTracker tracker(beta, kShare);
    std::optional<std::size_t> pendingDuringLateFlyback;
    for (std::size_t k = 0; k < s.size(); ++k)
    {
        tracker.add(s[k]);
        if (k == 27) // the second sample of the late-qualifying flyback: under way, not yet full
            pendingDuringLateFlyback = tracker.pendingOnset();
    }
    EXPECT_EQ(tracker.onsets(), (std::vector<std::size_t>{26, 37}));
    EXPECT_EQ(pendingDuringLateFlyback, std::optional<std::size_t>(26));
    EXPECT_FALSE(tracker.pendingOnset().has_value()); // the last one already counts
    expectSameAsOfflineAtEverySample(s, beta, 1);
}

} // namespace ROSIN_FILE_LOCAL
