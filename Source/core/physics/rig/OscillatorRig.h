#pragma once
// [Smith2000]'s rig as one more linear system behind the same friction laws as the string: a single damped
// mode
//     m x'' + R x' + S x = f(t)                                      ([Smith2000] eq. 1)
// driven at its contact point by the friction force f of a rosin-coated rod moving at v_rod under a normal
// load N. The mode is a ModalBank of one mode (impulse invariance with the exact direct term, as for the
// string modes), so the contact sees the load line v = v_h + y0 f and any FrictionLaw solves it with
// JunctionInput{v_h - v_rod, 1/y0, N}.
// Why a band correction: a sampled mode's velocity response has a zero near z = -1 (at -|p|^2), so a sticking
// contact (a velocity constraint) would invert it and let the friction force ring at Nyquist, decaying only
// with the mode's own damping (~30 ms here), which moves every breakaway. As in BowedStringVoice, a term
// c (1 - z^-1) is added to the contact admittance. For a mass, (T/2m)(z+1)/(z-1) + c (z-1)/z has its other
// zeros at the roots of (1+g) z^2 + (1-2g) z + g, g = 2mc/T. g = 1 (c = T/2m, y0 = T/m: a free mass over one
// backward-Euler step) puts them at 0.25 +- 0.66i, |z| = 0.71: after a capture the force settles in ~20
// samples. A smaller g settles faster (a double root at -1/3 for g = 1/8) but stiffens the load line, so the
// velocity gap a capture closes within one sample costs an impulsive force beyond the static limit: spurious
// one-sample slips, and a stick-slip frequency that depended on the sample rate (42 Hz instead of 34 at
// 48 kHz). Re c (1 - e^-iwT) >= 0 keeps the contact passive; at 108 Hz the change is (omega T)^2 / 2 ~ 1e-4.
// Real-time contract, as BowedStringVoice: prepare() allocates; reset() and step() never allocate.
#include <memory>

#include "core/physics/friction/FrictionLaw.h"
#include "core/physics/modal/ModalBank.h"
#include "core/physics/modal/ModalKernels.h"
#include "core/physics/rig/OscillatorRigParameters.h"

namespace rosin::physics
{

/// Per-sample drive of the rig, SI units.
struct RigInput
{
    double normalForce = 0.0; ///< N, load of the rod on the oscillator (>= 0)
    double rodVelocity = 0.0; ///< v_rod, m/s
};

/// What one sample produced, at the contact point.
struct RigSample
{
    double displacement = 0.0;       ///< x, m
    double velocity = 0.0;           ///< v = x', m/s
    double acceleration = 0.0;       ///< x'', m/s^2
    double frictionForce = 0.0;      ///< f, N: force of the rod on the oscillator
    double slidingSpeed = 0.0;       ///< v - v_rod, m/s (> 0: the oscillator overtakes the rod)
    double rodVelocity = 0.0;        ///< v_rod used this sample, m/s
    double normalForce = 0.0;        ///< N used this sample
    double supportForce = 0.0;       ///< S x + R v: force of the oscillator on its clamp, N
    double contactTemperature = 0.0; ///< K above ambient (0 for friction-curve laws)
    bool sticking = true;
    /// mu = f / N (0 without load): the quantity of [Smith2000] Figs. 2c and 6.
    double frictionCoefficient() const noexcept
    {
        return normalForce > 0.0 ? frictionForce / normalForce : 0.0;
    }
};

class OscillatorRig
{
  public:
    /// Off the audio thread: validates the rig (std::invalid_argument), discretises it and prepares the law.
    void prepare(const OscillatorRigParameters& rig, std::unique_ptr<FrictionLaw> friction,
                 double sampleRate);
    /// Oscillator at rest, law state cleared. Real-time safe.
    void reset() noexcept;
    /// Advance one sample. Real-time safe.
    RigSample step(const RigInput& in) noexcept;

    /// y0, s/kg: the instantaneous admittance at the contact (v = v_h + y0 f).
    double instantaneousAdmittance() const noexcept { return y0_; }
    double sampleRate() const noexcept { return sampleRate_; }
    const OscillatorRigParameters& parameters() const noexcept { return rig_; }
    const FrictionLaw& friction() const noexcept { return *friction_; }
    /// True if the last step produced a non-finite state and the rig reset itself.
    bool recoveredFromRunaway() const noexcept { return recovered_; }

  private:
    OscillatorRigParameters rig_;
    std::unique_ptr<FrictionLaw> friction_;
    ModalBank mode_;
    OutputWeights xWeights_, vWeights_, aWeights_;
    double gain_ = 1.0;                                 ///< 1/m: the mode's unit input is f/m
    ModalReal gainIn_ = 1.0f;                           ///< gain_ in the modal kernels' number type
    double xDirect_ = 0, vDirect_ = 0, aDirect_ = 0;    ///< direct terms per newton
    double xHistory_ = 0, vHistory_ = 0, aHistory_ = 0; ///< outputs of the state before this sample's force
    double y0_ = 0.0;
    double bandCorrection_ = 0.0; ///< c, s/kg
    double previousForce_ = 0.0;  ///< f of the previous sample, N
    double sampleRate_ = 48000.0;
    bool recovered_ = false;
};

} // namespace rosin::physics
