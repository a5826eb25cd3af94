#pragma once
// Bending stiffness in the waveguide (reference §4.2, f_n = n f0 sqrt(1 + B n^2)): a stiff string's higher
// partials travel faster, so the loop's delay must fall with frequency. A cascade of M equal first-order
// allpasses (a + z^-1) / (1 + a z^-1) with a < 0 has a phase delay that falls from (1 - a)/(1 + a) per
// section at DC; M and a are fitted (least squares over the partials below 4 kHz) to the fall the stiff
// string needs relative to its fundamental, and the delay line is shortened by the cascade's delay at f0.
#include <vector>

namespace rosin::discovery
{

class DispersionAllpass
{
  public:
    DispersionAllpass() = default;
    /// For a loop of `loopSamples` at f0 with inharmonicity B (B = pi^2 EI / (P L^2)). B <= 0: a
    /// pass-through.
    DispersionAllpass(double loopSamples, double f0, double inharmonicity, double sampleRate);

    double process(double x) noexcept
    {
        for (auto& s : state_)
        {
            const double y = a_ * x + s;
            s = x - a_ * y;
            x = y;
        }
        return x;
    }
    /// Phase delay of the cascade at f (Hz), samples.
    double phaseDelay(double frequencyHz) const noexcept;
    int sections() const noexcept { return static_cast<int>(state_.size()); }

  private:
    double a_ = 0.0, sampleRate_ = 48000.0;
    std::vector<double> state_;
};

} // namespace rosin::discovery
