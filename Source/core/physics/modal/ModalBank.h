#pragma once
// A bank of independent damped modes  q'' + 2 sigma q' + omega^2 q = x(t)  (unit input), discretised by
// impulse invariance: the input is a train of impulses of area T x[k], each mode's state advances exactly
// (digital pole p = exp(s T), so frequencies and decay times are exact at any sample rate), and an output
// at sample k is the average of its values just before and just after the impulse k (the trapezoidal
// rule applied to the convolution integral, as in Green's-function bowed-string simulations).
//
// Why not the bilinear transform: it puts a zero at z = -1 in every mode, so the summed bow-point
// admittance vanishes at Nyquist and a sticking contact (a velocity constraint) lets the friction force
// alternate sample by sample without decay. Impulse invariance keeps a non-zero admittance at Nyquist.
//
// State: one complex number per mode, w~[k] = p (w~[k-1] + T x[k-1]), everything known before the current
// input. An output is then y[k] = 2 Re(rho w~[k]) + D x[k]. The direct term D is about half the impulse
// (T Re(rho)) and is set exactly so that every output has its continuous DC gain: 1/omega^2 for
// displacement, 0 for velocity and acceleration. Without that, sampling a damped mode's impulse response
// leaves a small DC velocity gain, and a string held by a sticking bow creeps (by 2 % in 30 ms with the
// cello D's torsional Q of 45). Arrays are split (re/im) to vectorise.
#include <complex>
#include <vector>

namespace rosin::physics
{

/// The number type of the modal state, poles, input gains and output weights: the per-sample updates run in
/// it, so single precision puts twice as many modes in each vector instruction. The coefficients of the
/// junction solve (residues, direct terms) stay double; a direct term is computed from the rounded pole, so
/// every output keeps its exact DC gain.
using ModalReal = float;

/// The modal kernels advance modes in blocks of this many (one AVX-512 register of floats). Owners pad their
/// banks to whole blocks with silent modes (zero input gains, so their state stays zero), so no scalar tail
/// runs; an unpadded bank is still advanced correctly, its last partial block one mode at a time.
inline constexpr int kModalBlock = 16;

/// What a mode output measures.
enum class ModalOutput
{
    Displacement,
    Velocity,
    Acceleration
};

/// A mode's physical description before discretisation.
struct ModeSpec
{
    double angularFrequency = 0.0; ///< omega, rad/s
    double lossFactor = 0.0;       ///< eta = 1/Q (sigma = eta omega / 2)
};

class ModalBank
{
  public:
    /// Allocates. Modes must satisfy 0 < omega < pi * sampleRate.
    void configure(const std::vector<ModeSpec>& modes, double sampleRate);
    /// Recomputes poles for new mode specs of the same count, keeping the state (no allocation).
    void retune(const ModeSpec* modes, int count) noexcept;
    void reset() noexcept;
    int size() const noexcept { return static_cast<int>(pRe.size()); }
    double timeStep() const noexcept { return T_; }

    /// Complex output coefficient rho of mode n for an output kind: y_n = 2 Re(rho w_n) (+ x for accel.).
    std::complex<double> residue(int n, ModalOutput kind) const noexcept;
    /// Direct feedthrough of mode n's output of that kind on the current input x[k].
    double direct(int n, ModalOutput kind) const noexcept;
    /// omega^2 of mode n (the continuous mode's stiffness per unit modal mass), 1/s^2.
    double modalStiffness(int n) const noexcept;
    /// Output of mode n at the last advanced step k, given the input x[k] used then.
    double outputAtLastStep(int n, ModalOutput kind, double x) const noexcept;
    /// Current value of one output of mode n, given the current input x (after history): for inspection.
    double value(int n, ModalOutput kind, double x) const noexcept;

    // Split arrays (public for the kernels; treat as read-only outside ModalKernels).
    std::vector<ModalReal> pRe, pIm;     ///< digital pole p
    std::vector<ModalReal> wRe, wIm;     ///< state w~
    std::vector<std::complex<double>> s; ///< continuous pole (upper half plane)

  private:
    double T_ = 1.0 / 48000.0;
    void setPole(int n, const ModeSpec& spec) noexcept;
};

} // namespace rosin::physics
