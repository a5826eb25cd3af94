#pragma once
// A bank of independent damped modes  q'' + 2 sigma q' + omega^2 q = x(t)  (unit input), discretised with
// the bilinear (trapezoidal) rule. Before discretising, each continuous pole is moved to
//     s~ = (2/T) (p - 1) / (p + 1),   p = exp(s T),
// so that the digital pole is exactly exp(s T): every mode rings at its true frequency and decays at its true
// rate at any sample rate, while the scheme keeps the trapezoidal rule's direct feedthrough (needed by the
// bow junction) and its passivity (it is the trapezoidal rule applied to a slightly stiffer passive system).
//
// State: one complex number per mode, w~[k] = p w~[k-1] + (1 + p) K1 x[k-1], which holds everything known
// before the current input. Any output y = Re(rho w) is then  history + direct * x[k]  (ModalBank::output*).
// Arrays are stored split (re/im) so the per-sample loops vectorise.
#include <complex>
#include <vector>

namespace rosin::physics
{

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

    /// Complex output coefficient rho of mode n for an output kind: y_n = 2 Re(rho w_n) (+ x for accel.).
    std::complex<double> residue(int n, ModalOutput kind) const noexcept;
    /// Direct feedthrough of mode n's output of that kind on the current input x[k].
    double direct(int n, ModalOutput kind) const noexcept;
    /// "Stiffness" |s~|^2 of mode n (the discretised mode's omega^2), 1/s^2.
    double modalStiffness(int n) const noexcept;
    /// Current value of one output of mode n, given the current input x (after history): for inspection.
    double value(int n, ModalOutput kind, double x) const noexcept;

    // Split arrays (public for the kernels; treat as read-only outside ModalKernels).
    std::vector<double> pRe, pIm; ///< digital pole p
    std::vector<double> dRe, dIm; ///< state input gain (1 + p) K1
    std::vector<double> wRe, wIm; ///< state w~
    std::vector<std::complex<double>> s;  ///< moved continuous pole s~ (upper half plane)
    std::vector<std::complex<double>> k1; ///< K1 = T / (2 - s~ T)

private:
    double T_ = 1.0 / 48000.0;
    void setPole(int n, const ModeSpec& spec) noexcept;
};

} // namespace rosin::physics
