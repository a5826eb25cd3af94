// The start of a constant-acceleration stroke read back from a recorded bow velocity v = a (t - t0): against
// the t0 that made the record, within the standard error the least-squares line predicts, 2 sigma/(a sqrt n).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/analysis/GestureStart.h"

using namespace rosin::analysis;

namespace ROSIN_FILE_LOCAL
{
constexpr double kFs = 44100.0;

std::vector<double> strokeVelocity(double a, double t0, double seconds, double noiseRms, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, noiseRms);
    std::vector<double> v(static_cast<std::size_t>(seconds * kFs));
    for (std::size_t k = 0; k < v.size(); ++k)
    {
        const double t = static_cast<double>(k) / kFs;
        v[k] = a * std::max(0.0, t - t0) + (noiseRms > 0.0 ? noise(rng) : 0.0);
    }
    return v;
}

GestureStartOptions options(double a, double noiseRms)
{
    GestureStartOptions o;
    o.sampleRate = kFs;
    o.acceleration = a;
    o.noiseRms = noiseRms;
    return o;
}

TEST(GestureStart, ExactRecordGivesTheDelayBack)
{
    for (double t0 : {0.0, 0.37e-3, 0.9e-3, 2.5e-3})
    {
        const auto est = gestureStartFromBowVelocity(strokeVelocity(1.5, t0, 0.4, 0.0, 1), options(1.5, 0.0));
        ASSERT_TRUE(est.has_value()) << t0;
        EXPECT_NEAR(*est, t0, 1e-9) << t0;
    }
}

TEST(GestureStart, NoisyRecordsScatterAsTheLineFitPredicts)
{
    const double a = 2.0, noise = 0.0069, seconds = 0.4;
    const double n = seconds * kFs - std::ceil(0.005 * kFs);
    const double predicted = 2.0 * noise / (a * std::sqrt(n));
    double sumSq = 0.0;
    const int trials = 200;
    for (int s = 0; s < trials; ++s)
    {
        const auto est =
            gestureStartFromBowVelocity(strokeVelocity(a, 0.6e-3, seconds, noise, s), options(a, noise));
        ASSERT_TRUE(est.has_value());
        sumSq += (*est - 0.6e-3) * (*est - 0.6e-3);
    }
    const double rms = std::sqrt(sumSq / trials);
    // The exact standard error of the intercept read back at t0 is sqrt(1/n + (t0 - tMean)^2/Sxx) sigma / a,
    // within 2 % of the 2 sigma/(a sqrt n) bound here; 200 draws estimate an rms to about 5 %.
    EXPECT_GT(rms, 0.8 * predicted);
    EXPECT_LT(rms, 1.2 * predicted);
}

TEST(GestureStart, TooNoisyForTheStatedAccuracyIsNotUsed)
{
    // a = 0.08 m/s^2 with 6.9 mm/s of noise: t0 known only to ~1.3 ms, above the 1 ms a lab knows anyway.
    const auto v = strokeVelocity(0.08, 0.5e-3, 0.4, 0.0069, 3);
    EXPECT_FALSE(gestureStartFromBowVelocity(v, options(0.08, 0.0069)).has_value());
    EXPECT_TRUE(gestureStartFromBowVelocity(v, options(0.08, 0.0)).has_value()); // noise not stated: trusted
}

TEST(GestureStart, ARecordThatIsNotTheStatedStrokeIsNotUsed)
{
    // Twice the stated acceleration, or a start 20 ms late, is a different gesture, not a latency.
    EXPECT_FALSE(gestureStartFromBowVelocity(strokeVelocity(3.0, 0.0, 0.4, 0.0, 1), options(1.5, 0.0)));
    EXPECT_FALSE(gestureStartFromBowVelocity(strokeVelocity(1.5, 0.02, 0.4, 0.0, 1), options(1.5, 0.0)));
    EXPECT_FALSE(gestureStartFromBowVelocity(std::vector<double>(100, 0.0), options(1.5, 0.0))); // too short
}

} // namespace ROSIN_FILE_LOCAL
