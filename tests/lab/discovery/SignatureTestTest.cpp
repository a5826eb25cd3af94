// The signature test of rosin discover (SignatureTest.h), on residuals whose answer is known: a smooth bias
// (offset and linear trends over the grid) is invisible to it whatever the signature; a signature that is
// itself a trend has nothing beyond the trends; a residual that is the signature scores its whole projected
// length, and its opposite the negative; unit white noise gives z with mean 0 and variance 1 (the matched
// filter of a projection, whatever the signature).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "lab/discovery/discover/SignatureTest.h"

using namespace rosin::discovery;

namespace ROSIN_FILE_LOCAL
{
/// A Guettler-like grid of 2 betas x 6 forces x 3 accelerations, one trial per cell.
struct Fixture
{
    ScanGrid grid;
    std::vector<std::size_t> trials;
    FeatureScatter scatter;
    Fixture()
    {
        grid.kind = ScanKind::Guettler;
        grid.betas = {0.05, 0.09};
        grid.forces = {0.2, 0.35, 0.6, 1.0, 1.7, 3.0};
        grid.motion = {0.5, 1.0, 2.0};
        for (std::size_t b = 0; b < 2; ++b)
            for (std::size_t f = 0; f < 6; ++f)
                for (std::size_t m = 0; m < 3; ++m)
                {
                    trials.push_back(trials.size());
                    grid.cells.push_back({b, f, m, {trials.back()}});
                }
        scatter.sigma.fill(0.5);
    }
    /// Values of one feature (static friction) per trial from the cell's log coordinates.
    template <typename Value> std::vector<TrialFeatures> features(Value value) const
    {
        std::vector<TrialFeatures> out(trials.size());
        for (const GridCell& c : grid.cells)
            out[c.trials[0]][kStaticFriction] =
                value(std::log(grid.betas[c.beta]), std::log(grid.forces[c.force]),
                      std::log(grid.motion[c.motion]));
        return out;
    }
};

const auto flat = [](double, double, double) { return 0.8; };
// A structure no offset or trend makes: static friction that saturates with force (as junction growth does).
const auto saturating = [](double, double lf, double) { return 0.8 + 0.05 * std::tanh(2.0 * lf); };

TEST(SignatureTest, ASmoothBiasIsInvisibleWhateverTheSignature)
{
    const Fixture x;
    const auto current = x.features(flat);
    const auto measured =
        x.features([](double lb, double lf, double la) { return 0.83 + 0.02 * lb - 0.03 * lf + 0.01 * la; });
    const auto candidate = x.features(saturating);
    const SignatureScore s = signatureScore(x.trials, x.grid, measured, current, candidate, x.scatter);
    EXPECT_NEAR(s.z, 0.0, 1e-9);
    EXPECT_GT(s.beyondTrends, 0.05);
    EXPECT_EQ(s.pairs, x.trials.size());
}

TEST(SignatureTest, ASignatureThatIsATrendHasNothingBeyondIt)
{
    const Fixture x;
    const auto current = x.features(flat);
    const auto candidate = x.features([](double, double lf, double) { return 0.8 + 0.04 * lf; });
    const SignatureScore s =
        signatureScore(x.trials, x.grid, x.features(saturating), current, candidate, x.scatter);
    EXPECT_LT(s.beyondTrends, 1e-12);
    EXPECT_EQ(s.z, 0.0);
}

TEST(SignatureTest, AResidualAlongTheSignatureScoresItsProjectedLength)
{
    const Fixture x;
    const auto current = x.features(flat);
    const auto candidate = x.features(saturating);
    // The measurement: the signature plus a smooth bias the projection removes.
    const auto measured = x.features([](double lb, double lf, double la)
                                     { return saturating(lb, lf, la) + 0.01 - 0.02 * lf + 0.03 * lb; });
    const SignatureScore s = signatureScore(x.trials, x.grid, measured, current, candidate, x.scatter);
    // g = r: z = |g'|, and |g'|^2 = beyondTrends |g|^2.
    double g2 = 0.0;
    for (std::size_t t : x.trials)
        g2 += std::pow((*candidate[t][kStaticFriction] - 0.8) / 0.5, 2);
    EXPECT_NEAR(s.z, std::sqrt(s.beyondTrends * g2), 1e-9);
    EXPECT_GT(s.z, 0.0);
    const auto opposite =
        x.features([](double lb, double lf, double la) { return 1.6 - saturating(lb, lf, la); });
    EXPECT_NEAR(signatureScore(x.trials, x.grid, opposite, current, candidate, x.scatter).z, -s.z, 1e-9);
}

TEST(SignatureTest, WhiteNoiseGivesAStandardNormalStatistic)
{
    const Fixture x;
    const auto current = x.features(flat);
    const auto candidate = x.features(saturating);
    std::mt19937 rng(17);
    std::normal_distribution<double> unit;
    const int draws = 4000;
    double sum = 0.0, sumSquares = 0.0;
    for (int d = 0; d < draws; ++d)
    {
        auto measured = current;
        for (auto& t : measured)
            *t[kStaticFriction] += 0.5 * unit(rng); // sigma 0.5
        const double z = signatureScore(x.trials, x.grid, measured, current, candidate, x.scatter).z;
        sum += z;
        sumSquares += z * z;
    }
    const double mean = sum / draws, variance = sumSquares / draws - mean * mean;
    std::printf("[ figures  ] signature z of white noise over %d draws: mean %+.3f, variance %.3f\n", draws,
                mean, variance);
    // Standard errors over 4000 draws: 0.016 on the mean, 0.022 on the variance.
    EXPECT_NEAR(mean, 0.0, 0.07);
    EXPECT_NEAR(variance, 1.0, 0.1);
}

} // namespace ROSIN_FILE_LOCAL
