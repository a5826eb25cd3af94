// The sub-sample period of a sawtooth (a Helmholtz bridge force) against the period it was made with.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/analysis/PeriodEstimate.h"

using namespace rosin::analysis;

namespace ROSIN_FILE_LOCAL
{
// A sawtooth of period P samples (rising, falling at once, as the bridge force of Helmholtz motion) with
// its fall spread over two samples (a band-limited corner) and white noise.
std::vector<double> sawtooth(double P, std::size_t n, double noise, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> w(0.0, noise);
    std::vector<double> x(n);
    for (std::size_t k = 0; k < n; ++k)
    {
        const double phase = std::fmod(static_cast<double>(k), P) / P;
        x[k] = (phase - 0.5) + (noise > 0.0 ? w(rng) : 0.0);
    }
    // Two-tap average: the corner rounded as a string's losses round it.
    for (std::size_t k = n - 1; k > 0; --k)
        x[k] = 0.5 * (x[k] + x[k - 1]);
    return x;
}

TEST(PeriodEstimate, SawtoothPeriodToAHundredthOfASample)
{
    for (double P : {300.0, 300.37, 299.81, 150.5})
    {
        const auto x = sawtooth(P, 8820, 0.0, 1);
        const auto est = refinedPeriod(x, 0, x.size(), std::round(P));
        ASSERT_TRUE(est.has_value()) << P;
        // 0.01 sample of 300 is 0.06 cent, a hundred times finer than a whole sample (5.8 cents).
        EXPECT_NEAR(*est, P, 0.01) << P;
    }
}

TEST(PeriodEstimate, NoiseOfTenPercentOfThePeakCostsLittle)
{
    const auto x = sawtooth(300.37, 8820, 0.1, 2);
    const auto est = refinedPeriod(x, 0, x.size(), 301.0);
    ASSERT_TRUE(est.has_value());
    EXPECT_NEAR(*est, 300.37, 0.1);
}

TEST(PeriodEstimate, TooShortOrOffTheSearchIsNothing)
{
    const auto x = sawtooth(300.0, 8820, 0.0, 1);
    EXPECT_FALSE(refinedPeriod(x, 0, 800, 300.0).has_value());      // under three periods
    EXPECT_FALSE(refinedPeriod(x, 0, x.size(), 250.0).has_value()); // the peak is beyond +-5 %
}

} // namespace ROSIN_FILE_LOCAL
