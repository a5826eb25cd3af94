#include "core/physics/modal/ModalKernels.h"

#include <array>

#include "core/physics/modal/KernelDispatch.h"
#include "core/physics/modal/VectorBlock.h"

namespace rosin::physics
{

namespace
{
const SimdLevel kLevel = simdLevel(); // chosen once, at load time

/// x_n = gainA_n a (+ gainB_n b); w~_n <- p_n (w~_n + T x_n); returns sum_n Re(o_n w~_n) for each output.
/// Modes go kModalBlock at a time, as kModalBlock / lanes vectors of `bytes` each (VectorBlock.h), each
/// output with one partial sum per vector; at the end the partial sums are halved into one and its lanes
/// halved into one value. That tree pairs mode l with l + 8, then l + 4, l + 2 and l + 1 whatever the width,
/// so every vector unit adds in the same order. A bank that is not padded to whole blocks (the rig's one
/// mode) ends in a scalar tail.
template <int bytes, int inputs, int outputs>
ROSIN_KERNEL_BODY std::array<double, outputs> advanceModes(ModalBank& bank, const ModalReal* gainA, double a,
                                                           const ModalReal* gainB, double b,
                                                           const OutputWeights* const (&o)[outputs]) noexcept
{
    constexpr int lanes = bytes / static_cast<int>(sizeof(ModalReal));
    constexpr int parts = kModalBlock / lanes;
    using Block = VectorBlock<ModalReal, lanes>;
    const int n = bank.size();
    const int whole = n - n % kModalBlock;
    ModalReal* __restrict wr = bank.wRe.data();
    ModalReal* __restrict wi = bank.wIm.data();
    const ModalReal* __restrict pr = bank.pRe.data();
    const ModalReal* __restrict pi = bank.pIm.data();
    const auto T = static_cast<ModalReal>(bank.timeStep());
    const auto fa = static_cast<ModalReal>(a), fb = static_cast<ModalReal>(b);
    const ModalReal* oRe[outputs];
    const ModalReal* oIm[outputs];
    for (int m = 0; m < outputs; ++m)
        oRe[m] = o[m]->re.data(), oIm[m] = o[m]->im.data();
    Block sums[outputs][parts] = {};
    for (int k0 = 0; k0 < whole; k0 += kModalBlock)
    {
#pragma GCC unroll 4
        for (int j = 0; j < parts; ++j)
        {
            const int k = k0 + j * lanes;
            Block x = loadBlock<Block>(gainA + k) * fa;
            if constexpr (inputs == 2)
                x += loadBlock<Block>(gainB + k) * fb;
            const Block oldIm = loadBlock<Block>(wi + k);
            const Block kicked = loadBlock<Block>(wr + k) + T * x; // w~[k+1] = p (w~[k] + T x[k])
            const Block re = loadBlock<Block>(pr + k), im = loadBlock<Block>(pi + k);
            const Block nr = re * kicked - im * oldIm;
            const Block ni = re * oldIm + im * kicked;
            storeBlock<Block>(wr + k, nr);
            storeBlock<Block>(wi + k, ni);
            for (int m = 0; m < outputs; ++m)
                sums[m][j] += loadBlock<Block>(oRe[m] + k) * nr - loadBlock<Block>(oIm[m] + k) * ni;
        }
    }
    ModalReal tail[outputs] = {};
    for (int k = whole; k < n; ++k)
    {
        ModalReal x = gainA[k] * fa;
        if constexpr (inputs == 2)
            x += gainB[k] * fb;
        const ModalReal kicked = wr[k] + T * x;
        const ModalReal nr = pr[k] * kicked - pi[k] * wi[k];
        const ModalReal ni = pr[k] * wi[k] + pi[k] * kicked;
        wr[k] = nr;
        wi[k] = ni;
        for (int m = 0; m < outputs; ++m)
            tail[m] += oRe[m][k] * nr - oIm[m][k] * ni;
    }
    std::array<double, outputs> out;
    for (int m = 0; m < outputs; ++m)
        out[m] = static_cast<double>(sumOfParts<ModalReal, lanes, parts>(sums[m]) + tail[m]);
    return out;
}

template <int bytes>
ROSIN_KERNEL_BODY TwoSums advanceTwoInputsTwoOutputsBody(ModalBank& bank, const ModalReal* gainA, double a,
                                                         const ModalReal* gainB, double b,
                                                         const OutputWeights& o1,
                                                         const OutputWeights& o2) noexcept
{
    const OutputWeights* const o[] = {&o1, &o2};
    const auto s = advanceModes<bytes, 2, 2>(bank, gainA, a, gainB, b, o);
    return {s[0], s[1]};
}

template <int bytes>
ROSIN_KERNEL_BODY double advanceOneInputOneOutputBody(ModalBank& bank, const ModalReal* gain, double a,
                                                      const OutputWeights& o1) noexcept
{
    const OutputWeights* const o[] = {&o1};
    return advanceModes<bytes, 1, 1>(bank, gain, a, nullptr, 0.0, o)[0];
}

template <int bytes>
ROSIN_KERNEL_BODY ThreeSums advanceOneInputThreeOutputsBody(ModalBank& bank, const ModalReal* gain, double a,
                                                            const OutputWeights& o1, const OutputWeights& o2,
                                                            const OutputWeights& o3) noexcept
{
    const OutputWeights* const o[] = {&o1, &o2, &o3};
    const auto s = advanceModes<bytes, 1, 3>(bank, gain, a, nullptr, 0.0, o);
    return {s[0], s[1], s[2]};
}

template <int bytes>
ROSIN_KERNEL_BODY FourSums advanceOneInputFourOutputsBody(ModalBank& bank, const ModalReal* gain, double a,
                                                          const OutputWeights& o1, const OutputWeights& o2,
                                                          const OutputWeights& o3,
                                                          const OutputWeights& o4) noexcept
{
    const OutputWeights* const o[] = {&o1, &o2, &o3, &o4};
    const auto s = advanceModes<bytes, 1, 4>(bank, gain, a, nullptr, 0.0, o);
    return {s[0], s[1], s[2], s[3]};
}

ROSIN_KERNEL_VARIANTS_BY_WIDTH(TwoSums, advanceTwoInputsTwoOutputs,
                               (ModalBank & bank, const ModalReal* gainA, double a, const ModalReal* gainB,
                                double b, const OutputWeights& o1, const OutputWeights& o2),
                               (bank, gainA, a, gainB, b, o1, o2))
ROSIN_KERNEL_VARIANTS_BY_WIDTH(double, advanceOneInputOneOutput,
                               (ModalBank & bank, const ModalReal* gain, double a, const OutputWeights& o1),
                               (bank, gain, a, o1))
ROSIN_KERNEL_VARIANTS_BY_WIDTH(ThreeSums, advanceOneInputThreeOutputs,
                               (ModalBank & bank, const ModalReal* gain, double a, const OutputWeights& o1,
                                const OutputWeights& o2, const OutputWeights& o3),
                               (bank, gain, a, o1, o2, o3))
ROSIN_KERNEL_VARIANTS_BY_WIDTH(FourSums, advanceOneInputFourOutputs,
                               (ModalBank & bank, const ModalReal* gain, double a, const OutputWeights& o1,
                                const OutputWeights& o2, const OutputWeights& o3, const OutputWeights& o4),
                               (bank, gain, a, o1, o2, o3, o4))
} // namespace

TwoSums advanceTwoInputsTwoOutputs(ModalBank& bank, const ModalReal* gainA, double a, const ModalReal* gainB,
                                   double b, const OutputWeights& o1, const OutputWeights& o2) noexcept
{
    ROSIN_KERNEL_DISPATCH(kLevel, advanceTwoInputsTwoOutputs, (bank, gainA, a, gainB, b, o1, o2));
}

double advanceOneInputOneOutput(ModalBank& bank, const ModalReal* gain, double a,
                                const OutputWeights& o1) noexcept
{
    ROSIN_KERNEL_DISPATCH(kLevel, advanceOneInputOneOutput, (bank, gain, a, o1));
}

ThreeSums advanceOneInputThreeOutputs(ModalBank& bank, const ModalReal* gain, double a,
                                      const OutputWeights& o1, const OutputWeights& o2,
                                      const OutputWeights& o3) noexcept
{
    ROSIN_KERNEL_DISPATCH(kLevel, advanceOneInputThreeOutputs, (bank, gain, a, o1, o2, o3));
}

FourSums advanceOneInputFourOutputs(ModalBank& bank, const ModalReal* gain, double a, const OutputWeights& o1,
                                    const OutputWeights& o2, const OutputWeights& o3,
                                    const OutputWeights& o4) noexcept
{
    ROSIN_KERNEL_DISPATCH(kLevel, advanceOneInputFourOutputs, (bank, gain, a, o1, o2, o3, o4));
}

} // namespace rosin::physics
