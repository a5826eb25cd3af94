#pragma once
// How bright a periodic bridge force is: the level of its upper harmonics relative to its lowest ones, in
// dB. In Helmholtz motion the bridge force is a sawtooth whose drop is the Helmholtz corner arriving at the
// bridge; the string's losses round that corner every period and the friction at the bow sharpens it again
// (Cremer's corner rounding [Cremer1984], [Notes §7]), so the balance sets how fast the harmonics fall.
// An ideal sawtooth has harmonic n at 1/n: harmonics 25-60 then carry -17.7 dB of the power of harmonics
// 1-4 (sum of 1/n^2; HarmonicTiltTest). The string's own losses rise with frequency (bending term) while
// the body's dominate the low modes, so a string losing more than its nominal loss law shows here: tripled
// losses take 1-1.5 dB off a cello D's Helmholtz motion, where harmonics 5-24 move by less than 0.5 dB.
//
// Computed from the power spectrum (Hann window) of a stretch of the signal, summed over bands of harmonic
// numbers [lowFirst - 0.5, lowLast + 0.5] and [highFirst - 0.5, highLast + 0.5] times the nominal
// fundamental: bands, not peaks, so a flattened Helmholtz period (a few cents) and a bow speeding up during
// the stretch do not matter.
#include <cstddef>
#include <optional>
#include <vector>

namespace rosin::analysis
{

struct HarmonicTiltOptions
{
    double sampleRate = 48000.0;
    double fundamentalHz = 146.8; ///< nominal f0 of the string
    int lowFirst = 1, lowLast = 4;
    int highFirst = 25, highLast = 60;
};

/// 10 log10(P_high / P_low) over samples [start, end) of `signal`; nullopt when the stretch is shorter than
/// four periods, the high band reaches Nyquist, or the low band carries no power.
std::optional<double> harmonicTiltDb(const std::vector<double>& signal, std::size_t start, std::size_t end,
                                     const HarmonicTiltOptions& options);

} // namespace rosin::analysis
