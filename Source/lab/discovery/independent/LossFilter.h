#pragma once
// Per-round-trip loss of one waveguide segment ([Notes §4.1], "DWG" bullet): a wave that travels for a time
// tau at frequency f loses the factor exp(-pi eta(f) f tau), eta = 1/Q the string's loss law. A one-pole
// low-pass g (1 - p) / (1 - p z^-1) is fitted to that target at two frequencies (the fundamental, where the
// decay time is measured, and a higher partial, which sets how fast the corner of the Helmholtz wave rounds
// off). Its phase delay at the fundamental is returned so the segment can shorten its delay line by as much
// and keep the pitch.
#include <functional>

namespace rosin::discovery
{

/// The loss factor eta(f) = 1/Q of a wave at frequency f (Hz).
using LossLaw = std::function<double(double frequencyHz)>;

/// Transverse loss law of [Notes] eq. (4.1) for a stiff string (P tension, m mass per length, EI bending
/// stiffness; etaF, etaB dimensionless, etaA in 1/s), plus a frequency-independent extra 1/Q and a factor on
/// the bending term (the generator's extra-damping forms; 0 and 1 for the nominal law).
LossLaw stringLossLaw(double tension, double massPerLength, double bendingStiffness, double etaF, double etaB,
                      double etaA, double extraEta = 0.0, double bendingFactor = 1.0);

class OnePoleLoss
{
  public:
    OnePoleLoss() = default;
    /// Fits the filter to exp(-pi eta(f) f tau) at f1 and f2 (Hz, f1 < f2 < fs/4) for a round trip of tau s.
    /// H(z) = 1 - g + g (1 - p) / (1 - p z^-1): unity at DC, so the string holds a static deflection as a
    /// real one does (a loop gain below 1 at DC would let a held string relax under the bow like a dashpot:
    /// the pre-slip rise of a slow Guettler start fell 8 % short of its parabola and the first slip came 5 %
    /// late). The loss law's decay applies to vibration; a string under a static load loses nothing.
    OnePoleLoss(const LossLaw& eta, double tau, double f1, double f2, double sampleRate);

    double process(double x) noexcept
    {
        y_ = (1.0 - pole_) * x + pole_ * y_;
        return x + gain_ * (y_ - x);
    }
    void reset() noexcept { y_ = 0.0; }

    double magnitude(double frequencyHz) const noexcept;
    /// Phase delay (samples) at frequencyHz.
    double phaseDelay(double frequencyHz) const noexcept;
    double pole() const noexcept { return pole_; }
    double gain() const noexcept { return gain_; } ///< g: the share of the signal that is low-passed

  private:
    double gain_ = 1.0, pole_ = 0.0, sampleRate_ = 48000.0;
    double y_ = 0.0;
};

} // namespace rosin::discovery
