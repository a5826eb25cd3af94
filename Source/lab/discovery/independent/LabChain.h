#pragma once
// The independent generator's measurement chain, between the simulated string (internal rate, twice the
// dataset's) and the dataset's samples, with what a real acquisition has and dataset.json does not state:
//   1. a start delay: the gesture starts up to 1 ms after the record's time zero (per trial);
//   2. the converter's anti-aliasing low-pass, a Butterworth (4th order; a family member may have 2nd or 6th)
//      with its corner drawn in 8-16 kHz (for a 44.1 kHz dataset; scaled with the rate otherwise), then every
//      second (third, fourth: the member's oversampling) sample;
//   3. a gain error per channel (+-3 %);
//   4. the stated first-order high-pass (sensor.highpassHz) on force channels, by the bilinear transform;
//   5. white noise of the stated sensor.noiseRms on every channel;
//   6. the plan's fault, if the trial failed.
// The bow force and motion scatter (1.5 %) is the plan's (SynthPlan::actual), shared with rosin synth-data.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "lab/discovery/Dataset.h"

namespace rosin::discovery
{

struct ChainDraw
{
    double cornerHz = 12000.0; ///< anti-aliasing corner
    std::vector<double> gains; ///< per dataset channel
    std::vector<std::pair<std::string, double>> values(const std::vector<Channel>& channels) const;
};

/// Drawn once per dataset; `sampleRate` is the dataset's.
ChainDraw drawChain(std::uint64_t seed, std::size_t channels, double sampleRate);
/// Start delay of a trial, s, uniform in [0, 1 ms].
double drawStartDelay(std::uint64_t seed, std::size_t trial);

inline constexpr double kGainTolerance = 0.03;
inline constexpr double kMaxStartDelay = 1e-3; ///< s

/// Butterworth low-pass of an even `order` (order / 2 bilinear biquads, corner pre-warped), in place, from
/// rest.
void antiAliasLowPass(std::vector<double>& x, double cornerHz, double sampleRate, int order = 4);
/// First-order high-pass (bilinear, pre-warped), in place, from rest.
void firstOrderHighPassBilinear(std::vector<double>& x, double cornerHz, double sampleRate);

/// Steps 1-3 on one channel at the internal rate (`decimation` x the dataset's): delayed by `delay` s,
/// low-passed (Butterworth of `order`), decimated and scaled by `gain`.
std::vector<double> acquire(const std::vector<double>& internal, double internalRate, double delay,
                            double cornerHz, double gain, int decimation = 2, int order = 4);

} // namespace rosin::discovery
