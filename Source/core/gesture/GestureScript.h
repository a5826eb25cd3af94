#pragma once
// A bow gesture as data: a list of timed segments, each holding or ramping the bow's control quantities.
// This is what a gesture script (Resources/docs/gesture-script.md) and the built-in specs ("steady:",
// "guettler:") parse into; BowGesture turns it into per-sample BowInput. JUCE-free.
#include <optional>
#include <vector>

namespace rosin::gesture
{

/// A quantity over one segment: linear in time from `from` (at the segment start) to `to` (at its end).
/// Without `from` the ramp starts where the previous segment left the quantity.
struct Ramp
{
    std::optional<double> from;
    double to = 0.0;

    static Ramp constant(double value) { return Ramp{value, value}; }
    static Ramp towards(double value) { return Ramp{std::nullopt, value}; }
};

/// One timed segment. Absent quantities hold the value the previous segment ended with.
struct Segment
{
    double seconds = 1.0;               ///< duration, s (> 0, <= 600)
    std::optional<Ramp> force;          ///< normal bow force F_b, N (0..20)
    std::optional<Ramp> speed;          ///< bow velocity v_b, m/s (-5..5); excludes `acceleration`
    std::optional<double> acceleration; ///< dv_b/dt, m/s^2 (-50..50), from the previous end velocity
    std::optional<Ramp> beta;           ///< bow-bridge distance / vibrating length (0.01..0.5)
    std::optional<Ramp> finger;         ///< vibrating length / open length (0.1..1, 1 = open string)
};

/// Values in force before the first segment (what an absent quantity of segment 0 holds).
struct GestureStart
{
    double force = 1.0;  ///< N
    double speed = 0.0;  ///< m/s: the bow starts at rest
    double beta = 0.1;   ///< usually the preset's default beta
    double finger = 1.0; ///< open string
};

struct GestureScript
{
    std::vector<Segment> segments;

    double totalSeconds() const
    {
        double total = 0.0;
        for (const auto& s : segments)
            total += s.seconds;
        return total;
    }
};

} // namespace rosin::gesture
