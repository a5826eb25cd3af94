#include "ModalKernels.h"

#include "KernelDispatch.h"

namespace rosin::physics
{

namespace
{
const SimdLevel kLevel = simdLevel(); // chosen once, at load time

ROSIN_KERNEL_BODY TwoSums advanceTwoInputsTwoOutputsBody(ModalBank& bank, const ModalReal* gainA, double a,
                                                         const ModalReal* gainB, double b,
                                                         const OutputWeights& o1,
                                                         const OutputWeights& o2) noexcept
{
    const int n = bank.size();
    ModalReal* __restrict wr = bank.wRe.data();
    ModalReal* __restrict wi = bank.wIm.data();
    const ModalReal* __restrict pr = bank.pRe.data();
    const ModalReal* __restrict pi = bank.pIm.data();
    const auto T = static_cast<ModalReal>(bank.timeStep());
    const auto fa = static_cast<ModalReal>(a), fb = static_cast<ModalReal>(b);
    const ModalReal* __restrict o1r = o1.re.data();
    const ModalReal* __restrict o1i = o1.im.data();
    const ModalReal* __restrict o2r = o2.re.data();
    const ModalReal* __restrict o2i = o2.im.data();
    ModalReal s1 = 0, s2 = 0;
#pragma omp simd reduction(+ : s1, s2)
    for (int k = 0; k < n; ++k)
    {
        const ModalReal x = gainA[k] * fa + gainB[k] * fb;
        const ModalReal kicked = wr[k] + T * x; // w~[k+1] = p (w~[k] + T x[k])
        const ModalReal nr = pr[k] * kicked - pi[k] * wi[k];
        const ModalReal ni = pr[k] * wi[k] + pi[k] * kicked;
        wr[k] = nr;
        wi[k] = ni;
        s1 += o1r[k] * nr - o1i[k] * ni;
        s2 += o2r[k] * nr - o2i[k] * ni;
    }
    return {s1, s2};
}

ROSIN_KERNEL_BODY double advanceOneInputOneOutputBody(ModalBank& bank, const ModalReal* gain, double a,
                                                      const OutputWeights& o1) noexcept
{
    const int n = bank.size();
    ModalReal* __restrict wr = bank.wRe.data();
    ModalReal* __restrict wi = bank.wIm.data();
    const ModalReal* __restrict pr = bank.pRe.data();
    const ModalReal* __restrict pi = bank.pIm.data();
    const auto T = static_cast<ModalReal>(bank.timeStep());
    const auto fa = static_cast<ModalReal>(a);
    const ModalReal* __restrict o1r = o1.re.data();
    const ModalReal* __restrict o1i = o1.im.data();
    ModalReal s1 = 0;
#pragma omp simd reduction(+ : s1)
    for (int k = 0; k < n; ++k)
    {
        const ModalReal x = gain[k] * fa;
        const ModalReal kicked = wr[k] + T * x; // w~[k+1] = p (w~[k] + T x[k])
        const ModalReal nr = pr[k] * kicked - pi[k] * wi[k];
        const ModalReal ni = pr[k] * wi[k] + pi[k] * kicked;
        wr[k] = nr;
        wi[k] = ni;
        s1 += o1r[k] * nr - o1i[k] * ni;
    }
    return s1;
}

ROSIN_KERNEL_BODY ThreeSums advanceOneInputThreeOutputsBody(ModalBank& bank, const ModalReal* gain, double a,
                                                            const OutputWeights& o1, const OutputWeights& o2,
                                                            const OutputWeights& o3) noexcept
{
    const int n = bank.size();
    ModalReal* __restrict wr = bank.wRe.data();
    ModalReal* __restrict wi = bank.wIm.data();
    const ModalReal* __restrict pr = bank.pRe.data();
    const ModalReal* __restrict pi = bank.pIm.data();
    const auto T = static_cast<ModalReal>(bank.timeStep());
    const auto fa = static_cast<ModalReal>(a);
    const ModalReal* __restrict o1r = o1.re.data();
    const ModalReal* __restrict o1i = o1.im.data();
    const ModalReal* __restrict o2r = o2.re.data();
    const ModalReal* __restrict o2i = o2.im.data();
    const ModalReal* __restrict o3r = o3.re.data();
    const ModalReal* __restrict o3i = o3.im.data();
    ModalReal s1 = 0, s2 = 0, s3 = 0;
#pragma omp simd reduction(+ : s1, s2, s3)
    for (int k = 0; k < n; ++k)
    {
        const ModalReal x = gain[k] * fa;
        const ModalReal kicked = wr[k] + T * x; // w~[k+1] = p (w~[k] + T x[k])
        const ModalReal nr = pr[k] * kicked - pi[k] * wi[k];
        const ModalReal ni = pr[k] * wi[k] + pi[k] * kicked;
        wr[k] = nr;
        wi[k] = ni;
        s1 += o1r[k] * nr - o1i[k] * ni;
        s2 += o2r[k] * nr - o2i[k] * ni;
        s3 += o3r[k] * nr - o3i[k] * ni;
    }
    return {s1, s2, s3};
}

ROSIN_KERNEL_BODY FourSums advanceOneInputFourOutputsBody(ModalBank& bank, const ModalReal* gain, double a,
                                                          const OutputWeights& o1, const OutputWeights& o2,
                                                          const OutputWeights& o3,
                                                          const OutputWeights& o4) noexcept
{
    const int n = bank.size();
    ModalReal* __restrict wr = bank.wRe.data();
    ModalReal* __restrict wi = bank.wIm.data();
    const ModalReal* __restrict pr = bank.pRe.data();
    const ModalReal* __restrict pi = bank.pIm.data();
    const auto T = static_cast<ModalReal>(bank.timeStep());
    const auto fa = static_cast<ModalReal>(a);
    const ModalReal* __restrict o1r = o1.re.data();
    const ModalReal* __restrict o1i = o1.im.data();
    const ModalReal* __restrict o2r = o2.re.data();
    const ModalReal* __restrict o2i = o2.im.data();
    const ModalReal* __restrict o3r = o3.re.data();
    const ModalReal* __restrict o3i = o3.im.data();
    const ModalReal* __restrict o4r = o4.re.data();
    const ModalReal* __restrict o4i = o4.im.data();
    ModalReal s1 = 0, s2 = 0, s3 = 0, s4 = 0;
#pragma omp simd reduction(+ : s1, s2, s3, s4)
    for (int k = 0; k < n; ++k)
    {
        const ModalReal x = gain[k] * fa;
        const ModalReal kicked = wr[k] + T * x; // w~[k+1] = p (w~[k] + T x[k])
        const ModalReal nr = pr[k] * kicked - pi[k] * wi[k];
        const ModalReal ni = pr[k] * wi[k] + pi[k] * kicked;
        wr[k] = nr;
        wi[k] = ni;
        s1 += o1r[k] * nr - o1i[k] * ni;
        s2 += o2r[k] * nr - o2i[k] * ni;
        s3 += o3r[k] * nr - o3i[k] * ni;
        s4 += o4r[k] * nr - o4i[k] * ni;
    }
    return {s1, s2, s3, s4};
}

ROSIN_KERNEL_VARIANTS(TwoSums, advanceTwoInputsTwoOutputs,
                      (ModalBank & bank, const ModalReal* gainA, double a, const ModalReal* gainB, double b,
                       const OutputWeights& o1, const OutputWeights& o2),
                      (bank, gainA, a, gainB, b, o1, o2))
ROSIN_KERNEL_VARIANTS(double, advanceOneInputOneOutput,
                      (ModalBank & bank, const ModalReal* gain, double a, const OutputWeights& o1),
                      (bank, gain, a, o1))
ROSIN_KERNEL_VARIANTS(ThreeSums, advanceOneInputThreeOutputs,
                      (ModalBank & bank, const ModalReal* gain, double a, const OutputWeights& o1,
                       const OutputWeights& o2, const OutputWeights& o3),
                      (bank, gain, a, o1, o2, o3))
ROSIN_KERNEL_VARIANTS(FourSums, advanceOneInputFourOutputs,
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
