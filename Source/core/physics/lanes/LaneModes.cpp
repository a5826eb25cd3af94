#include "core/physics/lanes/LaneModes.h"

#include <algorithm>
#include <cstring>

#include "core/physics/modal/KernelDispatch.h"
#include "core/physics/modal/VectorBlock.h"

namespace rosin::physics
{

namespace
{
// Four modes per pass, each with its own accumulators, so consecutive modes do not wait on one sum. assign()
// rounds the modes up to whole passes (the banks are padded far enough), so the passes need no tail.
constexpr int kUnroll = 4;
} // namespace

void LaneModes::assign(const ModalBank& bank, const ModalReal* a, const ModalReal* b, const OutputWeights* o1,
                       const OutputWeights* o2, const OutputWeights* o3)
{
    // The bank's trailing silent modes (padding to the one-voice kernels' blocks, modes parked above the
    // limit) are never driven, so their state stays zero: leaving them out is exact.
    modes = bank.size();
    while (modes > 0 && a[modes - 1] == ModalReal(0) && (b == nullptr || b[modes - 1] == ModalReal(0)))
        --modes;
    modes = paddedToWholeBlocks(modes, kUnroll);
    pRe = bank.pRe;
    pIm = bank.pIm;
    const auto T = static_cast<ModalReal>(bank.timeStep());
    gainA.assign(modes, ModalReal(0));
    gainB.assign(modes, ModalReal(0));
    for (int k = 0; k < modes; ++k)
    {
        gainA[k] = T * a[k];
        gainB[k] = b != nullptr ? T * b[k] : ModalReal(0);
    }
    out1 = o1 != nullptr ? *o1 : OutputWeights{};
    out2 = o2 != nullptr ? *o2 : OutputWeights{};
    out3 = o3 != nullptr ? *o3 : OutputWeights{};
    w.assign(modes, ModeState{});
}

void LaneModes::reset() noexcept
{
    std::fill(w.begin(), w.end(), ModeState{});
}

void LaneModes::resetLane(int lane) noexcept
{
    for (int k = 0; k < modes; ++k)
        w[k].re[lane] = w[k].im[lane] = ModalReal(0);
}

namespace
{
// `inputs` gains (1 or 2) and `outputs` weights (1 to 3): w~ <- p (w~ + x) per mode, outputs summed per lane.
template <int inputs, int outputs>
inline __attribute__((always_inline)) void advance(LaneModes& bank, const LaneValues& inA,
                                                   const LaneValues& inB, LaneValues* sums) noexcept
{
    // Copied in and out with memcpy: no function takes or returns a vector, so no ABI depends on AVX.
    LaneVector a, b;
    std::memcpy(&a, inA.v, sizeof a);
    std::memcpy(&b, inB.v, sizeof b);
    const OutputWeights* o[3] = {&bank.out1, &bank.out2, &bank.out3};
    LaneVector partial[outputs][kUnroll] = {};
    ModeState* __restrict w = bank.w.data();
    for (int k0 = 0; k0 < bank.modes; k0 += kUnroll)
    {
#pragma GCC unroll 4
        for (int j = 0; j < kUnroll; ++j)
        {
            const int k = k0 + j;
            const ModalReal pr = bank.pRe[k], pi = bank.pIm[k];
            LaneVector kicked = w[k].re + bank.gainA[k] * a;
            if constexpr (inputs == 2)
                kicked += bank.gainB[k] * b;
            const LaneVector nr = pr * kicked - pi * w[k].im;
            const LaneVector ni = pr * w[k].im + pi * kicked;
            w[k].re = nr;
            w[k].im = ni;
#pragma GCC unroll 3
            for (int m = 0; m < outputs; ++m)
                partial[m][j] += o[m]->re[k] * nr - o[m]->im[k] * ni;
        }
    }
    for (int m = 0; m < outputs; ++m)
    {
        const LaneVector total = (partial[m][0] + partial[m][1]) + (partial[m][2] + partial[m][3]);
        std::memcpy(sums[m].v, &total, sizeof total);
    }
}
} // namespace

namespace
{
// The lanes stay at x86-64-v3 at most: eight doubles fill an AVX2 pair, and AVX-512 was not faster here.
const SimdLevel kLevel = simdLevel() == SimdLevel::V4 ? SimdLevel::V3 : simdLevel();

ROSIN_KERNEL_BODY void advanceTwoInputsTwoOutputsBody(LaneModes& bank, const LaneValues& a,
                                                      const LaneValues& b, LaneValues& s1,
                                                      LaneValues& s2) noexcept
{
    LaneValues sums[2];
    advance<2, 2>(bank, a, b, sums);
    s1 = sums[0];
    s2 = sums[1];
}

ROSIN_KERNEL_BODY void advanceOneInputOneOutputBody(LaneModes& bank, const LaneValues& a,
                                                    LaneValues& s1) noexcept
{
    advance<1, 1>(bank, a, a, &s1);
}

ROSIN_KERNEL_BODY void advanceOneInputThreeOutputsBody(LaneModes& bank, const LaneValues& a, LaneValues& s1,
                                                       LaneValues& s2, LaneValues& s3) noexcept
{
    LaneValues sums[3];
    advance<1, 3>(bank, a, a, sums);
    s1 = sums[0];
    s2 = sums[1];
    s3 = sums[2];
}

ROSIN_KERNEL_VARIANTS(void, advanceTwoInputsTwoOutputs,
                      (LaneModes & bank, const LaneValues& a, const LaneValues& b, LaneValues& s1,
                       LaneValues& s2),
                      (bank, a, b, s1, s2))
ROSIN_KERNEL_VARIANTS(void, advanceOneInputOneOutput, (LaneModes & bank, const LaneValues& a, LaneValues& s1),
                      (bank, a, s1))
ROSIN_KERNEL_VARIANTS(void, advanceOneInputThreeOutputs,
                      (LaneModes & bank, const LaneValues& a, LaneValues& s1, LaneValues& s2, LaneValues& s3),
                      (bank, a, s1, s2, s3))
} // namespace

void advanceTwoInputsTwoOutputs(LaneModes& bank, const LaneValues& a, const LaneValues& b, LaneValues& s1,
                                LaneValues& s2) noexcept
{
    ROSIN_KERNEL_DISPATCH(kLevel, advanceTwoInputsTwoOutputs, (bank, a, b, s1, s2));
}

void advanceOneInputOneOutput(LaneModes& bank, const LaneValues& a, LaneValues& s1) noexcept
{
    ROSIN_KERNEL_DISPATCH(kLevel, advanceOneInputOneOutput, (bank, a, s1));
}

void advanceOneInputThreeOutputs(LaneModes& bank, const LaneValues& a, LaneValues& s1, LaneValues& s2,
                                 LaneValues& s3) noexcept
{
    ROSIN_KERNEL_DISPATCH(kLevel, advanceOneInputThreeOutputs, (bank, a, s1, s2, s3));
}

} // namespace rosin::physics
