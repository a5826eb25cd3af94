#pragma once
// When a constant-acceleration bow stroke starts in a recorded bow velocity. An acquisition does not start
// exactly with the gesture (a trigger latency, a machine that starts a little after the record), and a
// record's time zero is then not the gesture's: times measured from it (the first slip, the point at 0.6 t1
// where the creep index reads the rise) carry that offset. With the bow's velocity recorded, v = a (t - t0)
// after the start, and the line fitted to it gives t0 back.
#include <optional>
#include <vector>

namespace rosin::analysis
{

struct GestureStartOptions
{
    double sampleRate = 44100.0;
    double acceleration = 1.0; ///< nominal a of the stroke, m/s^2 (> 0)
    /// Noise of the velocity channel, m/s rms (0 = unknown: the fit is trusted).
    double noiseRms = 0.0;
    /// The fit skips the record's first samples, where the stroke may not have started yet (ours: 5 x the
    /// largest start delay we expect, 1 ms).
    double skipSeconds = 0.005;
    /// Largest standard error of t0 predicted from noiseRms (2 sigma / (a sqrt n) for a line read back at the
    /// start of its window) for which the estimate is used (ours: the ~1 ms a lab knows its time zero to;
    /// where the noise allows less, a stroke is slow, its first slip late and a latency matters less).
    double maxStandardError = 1e-3;
    double maxStart = 0.01;      ///< s; a later start is not a latency but a different gesture
    double slopeTolerance = 0.2; ///< the fitted a must be within this share of the nominal one
};

/// t0 in s (may be slightly negative through noise), or nullopt where the record is too short or too noisy
/// for the stated accuracy, or does not look like the stated stroke (slope off, start out of range).
std::optional<double> gestureStartFromBowVelocity(const std::vector<double>& bowVelocity,
                                                  const GestureStartOptions& options);

} // namespace rosin::analysis
