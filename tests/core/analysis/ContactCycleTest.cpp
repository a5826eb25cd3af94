// The bowed point's slip fraction and hysteresis-loop area against closed forms: ideal Helmholtz motion
// slips for beta of each period; an elliptic loop x = A cos(theta), y = B sin(theta) encloses pi A B, traced
// anticlockwise; a friction curve (y a function of x) encloses nothing; the recording's sign convention of
// the friction force does not change the answer.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/analysis/ContactCycle.h"

namespace ROSIN_FILE_LOCAL
{
using rosin::analysis::normalisedLoopArea;
using rosin::analysis::slipFraction;
constexpr double pi = std::numbers::pi;

TEST(ContactCycle, IdealHelmholtzMotionSlipsForBetaOfThePeriod)
{
    const double vb = 0.2;
    const std::size_t period = 300;
    for (double beta : {0.0899, 0.1428})
    {
        const auto slipSamples = static_cast<std::size_t>(std::round(beta * period));
        std::vector<double> v(30 * period), bow(v.size(), vb);
        for (std::size_t k = 0; k < v.size(); ++k)
            v[k] = k % period < slipSamples ? -vb * (1.0 - beta) / beta : vb;
        const auto f = slipFraction(v, bow, 0, v.size());
        ASSERT_TRUE(f);
        EXPECT_NEAR(*f, beta, 0.5 / period) << beta;
    }
    EXPECT_FALSE(slipFraction({1.0, 2.0}, {0.0, 0.0}, 0, 2)); // bow at rest
}

TEST(ContactCycle, EllipticLoopEnclosesPiABPerPeriodOverTheBowSpeed)
{
    const double V = 0.1, A = 0.3, B = 0.05, mu0 = 0.4, N = 2.0, D = 0.35; // D: mean sliding speed
    const std::size_t period = 400, periods = 10;
    std::vector<double> v(period * periods + 1), bow(v.size(), V), f(v.size()), reversed(v.size());
    for (std::size_t k = 0; k < v.size(); ++k)
    {
        const double theta = 2.0 * pi * static_cast<double>(k) / period;
        v[k] = V + A * std::cos(theta) - D;
        f[k] = N * (mu0 + B * std::sin(theta));
        reversed[k] = -f[k];
    }
    const double expected = pi * A * B / V;
    const auto area = normalisedLoopArea(v, bow, f, N, 0, v.size(), period);
    ASSERT_TRUE(area);
    EXPECT_NEAR(*area, expected, 2e-3 * expected);
    EXPECT_NEAR(*normalisedLoopArea(v, bow, reversed, N, 0, v.size(), period), expected, 2e-3 * expected);
    // A friction curve: mu a function of the sliding speed alone.
    std::vector<double> curve(v.size());
    for (std::size_t k = 0; k < v.size(); ++k)
        curve[k] = N * (mu0 + 0.3 * std::exp(-std::abs(v[k] - V) / 0.1));
    EXPECT_NEAR(*normalisedLoopArea(v, bow, curve, N, 0, v.size(), period), 0.0, 1e-6);
    EXPECT_FALSE(normalisedLoopArea(v, bow, f, N, 0, period, period)); // one period is too short
}

} // namespace ROSIN_FILE_LOCAL
