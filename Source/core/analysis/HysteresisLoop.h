#pragma once
// A friction/velocity hysteresis loop ([Smith2000] Fig. 2c and Fig. 6, [Galluzzo2017] Figs. 20-21): the
// friction force at the bowed point against the sliding speed v - v_b, over a chosen interval of a
// simulation, kept with the contact temperature so the figure can colour the loop by it. Written as CSV
// (time,slidingSpeed, frictionForce,contactTemperature), the input of `plot_scan.py loop`
// (Resources/docs/scan-format.md).
#include <string>
#include <vector>

#include "core/physics/voice/BowedStringVoice.h"

namespace rosin::analysis
{

struct LoopPoint
{
    double time = 0.0;               ///< s from the start of the render
    double slidingSpeed = 0.0;       ///< m/s, v - v_b
    double frictionForce = 0.0;      ///< N, force of the bow on the string
    double contactTemperature = 0.0; ///< K above ambient
};

class HysteresisLoop
{
  public:
    /// Keeps samples with from <= t < to (seconds); from >= 0, to > from.
    HysteresisLoop(double fromSeconds, double toSeconds, double sampleRate);

    /// Feed every sample of the render in order (the loop counts them to know the time).
    void add(const physics::VoiceSample& s);
    const std::vector<LoopPoint>& points() const noexcept { return points_; }
    /// Fraction of the kept samples in which the string and bow stick (dv = 0).
    double stickingFraction() const noexcept;
    /// Signed area enclosed in the (dv, f) plane per cycle, by the shoelace formula over the whole interval:
    /// > 0 when the loop runs anticlockwise in these axes, < 0 clockwise. N m/s. [Smith2000] and
    /// [Galluzzo2017] plot |mu| against |dv|; with the bow faster than the string (dv < 0, f > 0) that view
    /// mirrors dv, which flips the sense.
    double signedArea() const noexcept;
    /// The loop as CSV text: the header "time,slidingSpeed,frictionForce,contactTemperature", a row per
    /// sample.
    std::string csv() const;

  private:
    double from_, to_, sampleRate_;
    long index_ = 0;
    long sticking_ = 0;
    std::vector<LoopPoint> points_;
};

} // namespace rosin::analysis
