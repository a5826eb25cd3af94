// The runner-up of a search step (EffectSearch.h, rivalOf): the best other significant candidate, and
// whether the held-out trials prefer the named effect to it, by the same paired sign-flip test that judges
// an effect against the current model. Checked on shares whose answer is known: one candidate better on
// every trial (decided, p at the test's floor), two candidates alike trial by trial up to a sign pattern
// with mean zero (not decided).
#include <gtest/gtest.h>

#include <vector>

#include "lab/discovery/EffectCatalog.h"
#include "lab/discovery/discover/EffectSearch.h"

using namespace rosin::discovery;

namespace ROSIN_FILE_LOCAL
{
EffectScore candidate(const char* name, bool significant, double gain, std::vector<double> shares)
{
    EffectScore s;
    s.effect = findEffect(name);
    s.significant = significant;
    s.heldOutGain = gain;
    s.heldOutShares = std::move(shares);
    return s;
}

TEST(StepRival, NoneWhenNoOtherCandidateIsSignificant)
{
    const std::vector<EffectScore> tried{candidate("junction-growth", true, 0.5, {1, 1, 1}),
                                         candidate("hertz-contact", false, 0.6, {0, 0, 0})};
    EXPECT_FALSE(rivalOf(tried, tried[0], 0).has_value());
}

TEST(StepRival, ACandidateBetterOnEveryTrialIsDecided)
{
    std::vector<double> chosen(40), other(40);
    for (std::size_t i = 0; i < chosen.size(); ++i)
        chosen[i] = 1.0 + 0.1 * static_cast<double>(i % 7), other[i] = chosen[i] + 0.5;
    const std::vector<EffectScore> tried{candidate("junction-growth", true, 0.6, chosen),
                                         candidate("breakaway-jump", true, 0.4, other),
                                         candidate("ambient-temperature", true, 0.3, other)};
    const auto rival = rivalOf(tried, tried[0], 0);
    ASSERT_TRUE(rival.has_value());
    EXPECT_EQ(rival->index, 1u); // the better of the two significant others
    EXPECT_EQ(rival->test.pairs, 40u);
    EXPECT_LT(rival->test.pValue, 1e-3); // 2^-40 in truth; the test's floor is 1 / 20000
    EXPECT_TRUE(rival->decided());
}

TEST(StepRival, CandidatesAlikeTrialByTrialAreNotDecided)
{
    // The rival is worse on half the trials and better on the other half by the same amounts.
    std::vector<double> chosen(40), other(40);
    for (std::size_t i = 0; i < chosen.size(); ++i)
    {
        chosen[i] = 2.0;
        other[i] = 2.0 + (i % 2 == 0 ? 0.3 : -0.3) * (1.0 + static_cast<double>(i / 2 % 5));
    }
    const std::vector<EffectScore> tried{candidate("junction-growth", true, 0.55, chosen),
                                         candidate("breakaway-jump", true, 0.55, other)};
    const auto rival = rivalOf(tried, tried[1], 0);
    ASSERT_TRUE(rival.has_value());
    EXPECT_EQ(rival->index, 0u);
    EXPECT_GT(rival->test.pValue, 0.3); // mean difference exactly 0: about half of the flips reach it
    EXPECT_FALSE(rival->decided());
}

} // namespace ROSIN_FILE_LOCAL
