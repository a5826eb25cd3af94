#pragma once
// The per-sample inner loops over a ModalBank: feed each mode its input, advance its state, and sum the
// weighted outputs of the new state (the next sample's history). These loops are the voice's hot path.
// They are compiled once per vector-instruction level and picked at run time (function multi-versioning),
// so one binary uses AVX-512 where the machine has it and still runs everywhere else.
#include "core/physics/modal/ModalBank.h"

namespace rosin::physics
{

/// Output weights of one output channel: sum_n Re(o_n w_n), o_n = oRe + i oIm (usually 2 * rho_n * weight_n).
struct OutputWeights
{
    std::vector<ModalReal> re, im;
    void assign(int n) { re.assign(n, ModalReal(0)), im.assign(n, ModalReal(0)); }
    void set(int n, std::complex<double> o)
    {
        re[n] = static_cast<ModalReal>(o.real());
        im[n] = static_cast<ModalReal>(o.imag());
    }
};

struct TwoSums
{
    double first = 0.0, second = 0.0;
};
struct ThreeSums
{
    double first = 0.0, second = 0.0, third = 0.0;
};
struct FourSums
{
    double first = 0.0, second = 0.0, third = 0.0, fourth = 0.0;
};

/// x_n = gainA_n a + gainB_n b; advance; return the two output sums over the new state.
TwoSums advanceTwoInputsTwoOutputs(ModalBank& bank, const ModalReal* gainA, double a, const ModalReal* gainB,
                                   double b, const OutputWeights& o1, const OutputWeights& o2) noexcept;
/// x_n = gain_n a; advance; return the output sum over the new state.
double advanceOneInputOneOutput(ModalBank& bank, const ModalReal* gain, double a,
                                const OutputWeights& o1) noexcept;
/// x_n = gain_n a; advance; return three output sums over the new state.
ThreeSums advanceOneInputThreeOutputs(ModalBank& bank, const ModalReal* gain, double a,
                                      const OutputWeights& o1, const OutputWeights& o2,
                                      const OutputWeights& o3) noexcept;
/// x_n = gain_n a; advance; return four output sums over the new state (the body: displacement, velocity,
/// acceleration and radiated pressure in one pass).
FourSums advanceOneInputFourOutputs(ModalBank& bank, const ModalReal* gain, double a, const OutputWeights& o1,
                                    const OutputWeights& o2, const OutputWeights& o3,
                                    const OutputWeights& o4) noexcept;

} // namespace rosin::physics
