// The harmonic tilt of a bridge force against closed forms: an ideal sawtooth has harmonic n at 1/n, so
// harmonics 25-60 carry sum(1/n^2, 25..60) / sum(1/n^2, 1..4) of the low band's power; a sawtooth through a
// known filter H has the same sums weighted by |H(n f0)|^2. The analysis works on bands, so a drifting
// amplitude (an accelerating bow) and a pitch a few cents off the nominal one must not change it.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "core/analysis/HarmonicTilt.h"

namespace ROSIN_FILE_LOCAL
{
using rosin::analysis::harmonicTiltDb;
using rosin::analysis::HarmonicTiltOptions;
constexpr double pi = std::numbers::pi;

double sawtoothTiltDb(double (*powerGain)(double f), double f0)
{
    double low = 0.0, high = 0.0;
    for (int n = 1; n <= 4; ++n)
        low += powerGain(n * f0) / (n * n);
    for (int n = 25; n <= 60; ++n)
        high += powerGain(n * f0) / (n * n);
    return 10.0 * std::log10(high / low);
}

// A band-limited sawtooth (harmonics to 100) with slowly growing amplitude.
std::vector<double> sawtooth(double f0, double fs, std::size_t n, double (*amplitudeGain)(double f))
{
    std::vector<double> x(n, 0.0);
    for (int h = 1; h <= 100; ++h)
        for (std::size_t k = 0; k < n; ++k)
        {
            const double t = static_cast<double>(k) / fs;
            x[k] += (1.0 + 2.0 * t) * amplitudeGain(h * f0) * std::sin(2.0 * pi * h * f0 * t) / h;
        }
    return x;
}

constexpr double kCornerHz = 3000.0;
double flat(double)
{
    return 1.0;
}
double onePolePower(double f)
{
    return 1.0 / (1.0 + (f / kCornerHz) * (f / kCornerHz));
}
double onePoleAmplitude(double f)
{
    return std::sqrt(onePolePower(f));
}

TEST(HarmonicTilt, IdealSawtoothMatchesTheSumOfInverseSquares)
{
    const double fs = 44100.0, f0 = 146.83;
    const auto x = sawtooth(f0, fs, 8192, flat);
    HarmonicTiltOptions o;
    o.sampleRate = fs;
    o.fundamentalHz = f0;
    const auto tilt = harmonicTiltDb(x, 0, x.size(), o);
    ASSERT_TRUE(tilt);
    const double expected = sawtoothTiltDb(flat, f0);
    EXPECT_NEAR(expected, -17.68, 0.01);
    EXPECT_NEAR(*tilt, expected, 0.3);
}

TEST(HarmonicTilt, RoundedCornersLoseTheFilteredPower)
{
    const double fs = 44100.0, f0 = 146.83;
    const auto x = sawtooth(f0 * std::pow(2.0, -5.0 / 1200.0), fs, 8192, onePoleAmplitude); // 5 cents flat
    HarmonicTiltOptions o;
    o.sampleRate = fs;
    o.fundamentalHz = f0;
    const auto tilt = harmonicTiltDb(x, 0, x.size(), o);
    ASSERT_TRUE(tilt);
    const double expected = sawtoothTiltDb(onePolePower, f0);
    EXPECT_LT(expected, sawtoothTiltDb(flat, f0) - 5.0); // the filter matters (5.9 dB) ...
    EXPECT_NEAR(*tilt, expected, 0.3);                   // ... and is measured
}

TEST(HarmonicTilt, RefusesTooShortAStretchOrABandPastNyquist)
{
    const auto x = sawtooth(146.83, 44100.0, 8192, flat);
    HarmonicTiltOptions o;
    o.sampleRate = 44100.0;
    o.fundamentalHz = 146.83;
    EXPECT_FALSE(harmonicTiltDb(x, 0, 3 * 300, o)); // three periods
    o.sampleRate = 16000.0;                         // harmonic 60 of 146.83 Hz is past 8 kHz
    EXPECT_FALSE(harmonicTiltDb(x, 0, x.size(), o));
    EXPECT_FALSE(harmonicTiltDb(std::vector<double>(8192, 0.0), 0, 8192, HarmonicTiltOptions{}));
}

} // namespace ROSIN_FILE_LOCAL
