// The gap's arithmetic: the Student-t loss and its null mean, a one-sided feature counts as 3 sigma, the
// paired test's per-trial shares add up to the fitted objective, the chi-square test of a gap meets the
// table's quantile, and a model's sensitivity to its settings marks features that flip as not comparable; a
// category's scatter is the rate at which the measurement disagrees with itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "lab/discovery/discover/GapMeasure.h"
#include "lab/discovery/discover/ModelFormTolerance.h"
#include "lab/discovery/discover/ModelSensitivity.h"

using namespace rosin::discovery;

namespace ROSIN_FILE_LOCAL
{
TrialFeatures withFeature(std::size_t f, double v)
{
    TrialFeatures t;
    t[f] = v;
    return t;
}

FeatureScatter unitScatter(std::size_t trials)
{
    FeatureScatter s;
    s.sigma.fill(1.0);
    s.sensitivity.assign(trials, {});
    return s;
}

TEST(GapMeasure, AFeatureSeenOnOneSideCountsAsThreeSigma)
{
    EXPECT_DOUBLE_EQ(*normalisedDifference(kJump, 10.0, 0.0, 1.0), 10.0); // no clip: the loss is robust
    EXPECT_DOUBLE_EQ(*normalisedDifference(kJump, 0.0, 10.0, 1.0), -10.0);
    EXPECT_DOUBLE_EQ(*normalisedDifference(kJump, 1.5, 0.5, 0.5), 2.0);
    EXPECT_DOUBLE_EQ(*normalisedDifference(kJump, 1.0, std::nullopt, 1.0), kMissingZ);
    // Helmholtz-motion features: the reported gap compares them only where both sides show them; a fit
    // compares them where the measurement shows them, a model that misses the motion there 3 sigma off.
    EXPECT_FALSE(normalisedDifference(kHarmonicTilt, -20.0, std::nullopt, 1.0));
    const auto fitSide = HelmholtzTrials::MeasuredSide;
    EXPECT_DOUBLE_EQ(*normalisedDifference(kHarmonicTilt, -20.0, std::nullopt, 1.0, fitSide), kMissingZ);
    EXPECT_FALSE(normalisedDifference(kHarmonicTilt, std::nullopt, -20.0, 1.0, fitSide));
    EXPECT_DOUBLE_EQ(*normalisedDifference(kJump, 1.0, std::nullopt, 1.0, fitSide), kMissingZ);
    EXPECT_FALSE(normalisedDifference(kJump, 1.0, 0.0, std::numeric_limits<double>::quiet_NaN()));
}

TEST(GapMeasure, TheRegimeIsComparedAsACategory)
{
    // A mismatch weighs 1 / sqrt(q), q the measurement's own mismatch rate: z^2 averages 1 when the model
    // disagrees as often as the measurement disagrees with itself.
    EXPECT_DOUBLE_EQ(*normalisedDifference(kRegime, 2.0, 2.0, 0.25), 0.0);
    EXPECT_DOUBLE_EQ(*normalisedDifference(kRegime, 0.0, 4.0, 0.25), 2.0); // however far apart the codes
    EXPECT_DOUBLE_EQ(*normalisedDifference(kRegime, 4.0, 0.0, kMinMismatchRate), kMissingZ);
    TrialFeatures nominal = withFeature(kRegime, 0.0), same = withFeature(kRegime, 0.0),
                  other = withFeature(kRegime, 4.0);
    EXPECT_EQ(featureSensitivity(nominal, {same, same})[kRegime], 0.0);
    EXPECT_TRUE(std::isnan(featureSensitivity(nominal, {same, other})[kRegime]));
}

// A row of 8 cells along the force axis whose regime changes once (Helmholtz to raucous): 1 of 7 adjacent
// pairs disagree. With two repeats per cell that disagree in 2 of 8 cells, the repeats decide: q = 2 / 8.
TEST(FeatureScatter, ARegimesScatterIsItsMismatchRate)
{
    ScanGrid grid;
    std::vector<TrialFeatures> measured;
    for (std::size_t i = 0; i < 8; ++i)
    {
        grid.cells.push_back(GridCell{0, i, 0, {measured.size()}});
        measured.push_back(withFeature(kRegime, i < 3 ? 0.0 : 4.0));
    }
    FeatureScatter s = measureScatter(grid, measured, 48000.0);
    EXPECT_DOUBLE_EQ(s.sigma[kRegime], 1.0 / 7.0);
    EXPECT_EQ(s.method[kRegime], "neighbours");
    for (std::size_t i = 0; i < 8; ++i)
    {
        grid.cells[i].trials.push_back(measured.size());
        measured.push_back(withFeature(kRegime, (i == 2 || i == 5) ? 1.0 : *measured[i][kRegime]));
    }
    s = measureScatter(grid, measured, 48000.0);
    EXPECT_DOUBLE_EQ(s.sigma[kRegime], 2.0 / 8.0);
    EXPECT_EQ(s.method[kRegime], "repeats");
    // A grid that never disagrees with itself still allows one mismatch in nine.
    for (auto& t : measured)
        t[kRegime] = 0.0;
    s = measureScatter(grid, measured, 48000.0);
    EXPECT_DOUBLE_EQ(s.sigma[kRegime], kMinMismatchRate);
    EXPECT_EQ(s.method[kRegime], "resolution");
}

TEST(GapMeasure, TrialSharesAddUpToTheObjective)
{
    std::vector<TrialFeatures> measured, simulated;
    std::vector<std::size_t> trials;
    for (std::size_t t = 0; t < 12; ++t)
    {
        TrialFeatures m, s;
        m[kJump] = 0.1 * t, s[kJump] = 0.0;
        if (t % 3 == 0) // a rarer feature: its few trials carry as much weight as the common one's many
            m[kHarmonicTilt] = -20.0, s[kHarmonicTilt] = -21.5;
        measured.push_back(m), simulated.push_back(s), trials.push_back(t);
    }
    const auto scatter = unitScatter(12);
    const auto g = fitGap(trials, measured, simulated, scatter);
    const auto shares = objectiveShares(trials, measured, simulated, scatter);
    double sum = 0.0;
    for (double x : shares)
        sum += x;
    EXPECT_NEAR(sum, g.objective, 1e-12);
    EXPECT_NEAR(g.meanSquare[kHarmonicTilt], 2.25, 1e-12);
    EXPECT_NEAR(shares[3] - shares[1], robustLoss(1.5) / 4 / 2 + (robustLoss(0.3) - robustLoss(0.1)) / 12 / 2,
                1e-12);
}

// The null mean of the loss by a second method (Monte Carlo, 200000 normal draws: standard error 0.002), and
// a right model's gap near 0 while a model 2 sigma off everywhere is clearly not.
// The loophole the measured side closes: a candidate that loses the Helmholtz motion in the trials where its
// pitch was 10 sigma off must not fit better than the model that kept the motion there, while the reported
// gap (both sides) would call it better.
TEST(GapMeasure, AFitGainsNothingByLosingTheMotionWhereItWasWrong)
{
    std::vector<TrialFeatures> measured(8), kept(8), lost(8);
    std::vector<std::size_t> trials;
    for (std::size_t t = 0; t < 8; ++t)
    {
        measured[t][kPitchCents] = -10.0;
        kept[t][kPitchCents] = lost[t][kPitchCents] = t < 4 ? -10.2 : 0.0; // 10 sigma off in trials 4-7
        if (t >= 4)
            lost[t][kPitchCents].reset();
        trials.push_back(t);
    }
    const auto scatter = unitScatter(8);
    EXPECT_LT(measureGap(trials, measured, lost, scatter).objective,
              measureGap(trials, measured, kept, scatter).objective);
    const auto lostFit = fitGap(trials, measured, lost, scatter, kept);
    EXPECT_GE(lostFit.objective, fitGap(trials, measured, kept, scatter).objective);
    EXPECT_EQ(lostFit.count[kPitchCents], 8u);
    // Against a reference that also misses them, a lost trial costs 3 sigma.
    EXPECT_NEAR(fitGap(trials, measured, lost, scatter, lost).meanLoss[kPitchCents],
                (4.0 * robustLoss(0.2) + 4.0 * robustLoss(kMissingZ)) / 8.0, 1e-12);
}

// The verdict's tolerance: a tilt 1.5 dB off in every trial against a scatter of 0.5 dB is significant in
// units of the scatter alone (z = 3) and within the model-form tolerance of at least 1.5 dB (z <= 1.5 /
// sqrt(0.5^2 + 1.5^2) = 0.95); the regime, a category, keeps its mismatch rate. A feature the tolerance does
// not cover (tau 0: the slip fraction, which no tuning control recorded) keeps its sigma.
TEST(ModelFormTolerance, WidensTheVerdictsSigmaInQuadrature)
{
    FeatureScatter scatter = unitScatter(30);
    scatter.sigma[kHarmonicTilt] = 0.5;
    scatter.sigma[kRegime] = 0.25;
    const FeatureScatter wide = withModelFormTolerance(scatter);
    EXPECT_NEAR(wide.sigma[kHarmonicTilt], std::hypot(0.5, modelFormTolerance()[kHarmonicTilt]), 1e-12);
    EXPECT_DOUBLE_EQ(wide.sigma[kRegime], 0.25);
    ASSERT_GE(modelFormTolerance()[kHarmonicTilt], 1.5);
    ASSERT_EQ(modelFormTolerance()[kSlipFraction], 0.0);
    EXPECT_DOUBLE_EQ(wide.sigma[kSlipFraction], scatter.sigma[kSlipFraction]);
    std::vector<TrialFeatures> measured(30), simulated(30);
    std::vector<std::size_t> trials;
    for (std::size_t t = 0; t < 30; ++t)
        measured[t][kHarmonicTilt] = -20.0, simulated[t][kHarmonicTilt] = -21.5, trials.push_back(t);
    EXPECT_LT(gapSignificance(measureGap(trials, measured, simulated, scatter)).pValue, 1e-6);
    EXPECT_GT(gapSignificance(measureGap(trials, measured, simulated, wide)).pValue, 0.1);
}

TEST(GapMeasure, StudentLossNullMeanAndGapOfARightModel)
{
    std::mt19937_64 random(17);
    std::normal_distribution<double> normal;
    double sum = 0.0;
    constexpr int draws = 200000;
    for (int i = 0; i < draws; ++i)
        sum += robustLoss(normal(random));
    EXPECT_NEAR(nullLoss(), sum / draws, 0.01);
    std::vector<TrialFeatures> measured, right, off;
    std::vector<std::size_t> trials;
    for (std::size_t t = 0; t < 400; ++t)
    {
        const double z = normal(random);
        measured.push_back(withFeature(kJump, z));
        right.push_back(withFeature(kJump, 0.0));
        off.push_back(withFeature(kJump, -2.0));
        trials.push_back(t);
    }
    const auto scatter = unitScatter(400);
    EXPECT_LT(measureGap(trials, measured, right, scatter).gap[kJump], 0.35);
    EXPECT_GT(measureGap(trials, measured, off, scatter).gap[kJump], 1.2); // 1.43 expected
}

// What the clip it replaces could not do: shrinking a 6-sigma misfit to 3 sigma is an improvement, and one
// trial 20 sigma off weighs like fewer than eight 2-sigma trials, not like a hundred.
TEST(GapMeasure, LargeMisfitsCountButDoNotDominate)
{
    EXPECT_GT(robustLoss(6.0) - robustLoss(3.0), 4.0);
    EXPECT_LT(robustLoss(20.0), 8.0 * robustLoss(2.0)); // z^2 would weigh it as 100 of them
    EXPECT_NEAR(robustLoss(0.1), 0.01, 1e-4);           // ~z^2 for small z
}

TEST(GapMeasure, ChiSquareTestMeetsTheTableQuantile)
{
    // chi-square with 50 degrees of freedom: the 99th percentile is 76.154 (standard tables).
    GapSummary g;
    g.count[kJump] = 50;
    g.meanSquare[kJump] = 76.154 / 50.0;
    EXPECT_NEAR(gapSignificance(g).pValue, 0.01, 0.001);
    EXPECT_EQ(gapSignificance(g).feature, kJump);
    g.meanSquare[kJump] = 1.0; // what a right model gives
    EXPECT_GT(gapSignificance(g).pValue, 0.4);
    // Two features tested: Bonferroni doubles the smallest p.
    g.meanSquare[kJump] = 76.154 / 50.0;
    g.count[kCreep] = 50;
    g.meanSquare[kCreep] = 1.0;
    EXPECT_NEAR(gapSignificance(g).pValue, 0.02, 0.002);
}

TEST(ModelSensitivity, LargestDepartureOrNotComparableWhenAFeatureFlips)
{
    TrialFeatures nominal = withFeature(kTransientPeriods, 5.0);
    nominal[kJump] = 0.2;
    TrialFeatures up = withFeature(kTransientPeriods, 14.0);
    up[kJump] = 0.21;
    TrialFeatures down = withFeature(kJump, 0.17); // no Helmholtz motion at all
    const auto s = featureSensitivity(nominal, {up, down});
    EXPECT_NEAR(s[kJump], 0.03, 1e-12);
    EXPECT_TRUE(std::isnan(s[kTransientPeriods]));
    EXPECT_EQ(s[kCreep], 0.0);

    FeatureScatter scatter = unitScatter(1);
    scatter.sigma[kJump] = 0.04;
    scatter.sensitivity[0] = s;
    EXPECT_NEAR(scatter.trialSigma(0, kJump), 0.05, 1e-12);
    EXPECT_TRUE(std::isnan(scatter.trialSigma(0, kTransientPeriods)));
    EXPECT_EQ(scatter.trialSigma(5, kJump), 0.04); // no sensitivity known: the scatter alone
}

} // namespace ROSIN_FILE_LOCAL
