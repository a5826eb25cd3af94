#pragma once
// Bending stiffness in the waveguide ([Notes §4.2], f_n = n f0 sqrt(1 + B n^2)): a stiff string's higher
// partials travel faster, so the loop's delay must fall with frequency. A cascade of M equal first-order
// allpasses (a + z^-1) / (1 + a z^-1) with a < 0 has a phase delay that falls from (1 - a)/(1 + a) per
// section at DC; a is fitted (least squares over the partials up to harmonic ~60 or 10 kHz) to the fall the
// stiff string needs relative to its fundamental, and the delay lines are shortened by the cascade's delay
// at f0. The fit reaches up through the band where the Helmholtz corner's rounding shows (harmonics 25-60,
// analysis::HarmonicTilt): fitted to 4 kHz only, the partials at 7-10 kHz sat 20-50 cents flat of eq. 4.2 and
// the corner came out sharper (brighter) than the stiff string makes it.
//
// The cascade is designed for the whole loop and then shared between the two sides of the bow in proportion
// to their lengths (equal sections), as the stiffness is spread along the string.
#include <functional>
#include <vector>

namespace rosin::discovery
{

/// M equal sections of coefficient a: the whole loop's dispersion.
struct DispersionDesign
{
    double coefficient = 0.0;
    int sections = 0; ///< 0: no dispersion
};

/// For a loop of `loopSamples` at f0 with inharmonicity B (B = pi^2 EI / (P L^2)). B <= 0: no sections.
/// `otherDelay` (samples at f Hz, may be empty): the phase delay of the loop's other filters (the loss
/// filters), whose change with frequency the cascade makes up for too.
/// `fitTopHz`: the partials below it are fitted (10 kHz by default; never above 0.4 sampleRate).
DispersionDesign designDispersion(double loopSamples, double f0, double inharmonicity, double sampleRate,
                                  const std::function<double(double)>& otherDelay = {},
                                  double fitTopHz = 10000.0);

class DispersionAllpass
{
  public:
    DispersionAllpass() = default;
    /// `sections` sections of the design's coefficient (a share of its cascade).
    DispersionAllpass(const DispersionDesign& design, int sections, double sampleRate);

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
