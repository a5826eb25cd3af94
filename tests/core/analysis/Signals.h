#pragma once
// Synthetic bridge-force and sticking signals with known slips, for the lab tests. Each generator is
// written from the waveform's definition, independently of the analysis under test.
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace rosin::analysis::test
{

/// A signal and the solver-style sticking flag that produced it.
struct Synthetic
{
    std::vector<double> force;
    std::vector<bool> sticking;
    std::vector<std::size_t> onsets; ///< true slip onsets (first sliding sample)
};

/// Stick-slip with slips at `phases` (fractions of a cycle, ascending, first 0) in every cycle of
/// `cycleSamples` (from a quarter cycle in), each falling by its `falls` share of `amplitude` (shares sum to
/// 1), the force rising linearly in between, each slip lasting `slipSamples`. Optional Schelleng ripple:
/// `ripples` cosine ripples per cycle of relative size `rippleDepth` (the body's ~1/beta ripples).
inline Synthetic stickSlip(std::size_t length, double cycleSamples, const std::vector<double>& phases,
                           const std::vector<double>& falls, double amplitude, std::size_t slipSamples,
                           double ripples = 0.0, double rippleDepth = 0.0)
{
    Synthetic s;
    s.force.assign(length, 0.0);
    s.sticking.assign(length, true);
    // Slip instants over the whole signal, the first a quarter cycle in (a slip at sample 0 has no onset).
    struct Slip
    {
        std::size_t at;
        double fall;
    };
    std::vector<Slip> slips;
    for (double c = 0.25; c * cycleSamples < static_cast<double>(length); c += 1.0)
        for (std::size_t i = 0; i < phases.size(); ++i)
        {
            const auto at = static_cast<std::size_t>(std::lround((c + phases[i]) * cycleSamples));
            if (at < length)
                slips.push_back({at, falls[i]});
        }
    // The force rises by `amplitude` per cycle and drops by each fall; the mean is removed below.
    std::size_t next = 0;
    double level = 0.0;
    const double slope = amplitude / cycleSamples;
    for (std::size_t k = 0; k < length; ++k)
    {
        if (next < slips.size() && slips[next].at == k)
        {
            level -= slips[next].fall * amplitude;
            s.onsets.push_back(k);
            for (std::size_t j = k; j < std::min(length, k + slipSamples); ++j)
                s.sticking[j] = false;
            ++next;
        }
        const double ripple =
            rippleDepth * amplitude * std::cos(2.0 * M_PI * ripples * static_cast<double>(k) / cycleSamples);
        s.force[k] = level + ripple;
        level += slope;
    }
    return s;
}

/// Gaussian white noise of rms `rms` added in place (seeded: reproducible).
inline void addNoise(std::vector<double>& x, double rms, unsigned seed = 1)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0.0, rms);
    for (double& v : x)
        v += n(rng);
}

/// Largest |x|.
inline double peak(const std::vector<double>& x)
{
    double p = 0.0;
    for (double v : x)
        p = std::max(p, std::abs(v));
    return p;
}

/// A first-order high-pass at `cutoffHz` by the bilinear transform (a force sensor's low-frequency roll-off).
inline std::vector<double> highPass(const std::vector<double>& x, double cutoffHz, double sampleRate)
{
    const double w = std::tan(M_PI * cutoffHz / sampleRate);
    const double a = (1.0 - w) / (1.0 + w), g = 1.0 / (1.0 + w);
    std::vector<double> y(x.size());
    double xPrev = 0.0, yPrev = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k)
    {
        y[k] = g * (x[k] - xPrev) + a * yPrev;
        xPrev = x[k];
        yPrev = y[k];
    }
    return y;
}

/// A sensor: noise of `noiseOfPeak` times the signal's peak, then the high-pass.
inline std::vector<double> measured(const std::vector<double>& x, double noiseOfPeak, double cutoffHz,
                                    double sampleRate, unsigned seed = 7)
{
    std::vector<double> y = x;
    addNoise(y, noiseOfPeak * peak(x), seed);
    return cutoffHz > 0.0 ? highPass(y, cutoffHz, sampleRate) : y;
}

} // namespace rosin::analysis::test
