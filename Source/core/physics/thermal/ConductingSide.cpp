// One solid's conduction memory (ConductingSide.h; [Notes] eq. 2.9 with the washout of §2.3a).
#include "core/physics/thermal/ConductingSide.h"

#include <algorithm>
#include <cmath>

#include "core/physics/modal/KernelDispatch.h"
#include "core/physics/modal/VectorBlock.h"

namespace rosin::physics
{

namespace
{
const SimdLevel kLevel = simdLevel();

// Terms go kTermsPerBlock at a time, as vectors of the kernel's width (VectorBlock.h), summed in one order
// on every vector unit; prepare() pads the terms to whole blocks with silent ones (zero decay and weight).
constexpr int kTermsPerBlock = 8;

template <int bytes>
ROSIN_KERNEL_BODY double advanceHistoryBody(double* __restrict h, const double* __restrict r,
                                            const double* __restrict w, int terms, double scaledFlux,
                                            double washout) noexcept
{
    constexpr int lanes = bytes / static_cast<int>(sizeof(double));
    constexpr int parts = kTermsPerBlock / lanes;
    using Block = VectorBlock<double, lanes>;
    Block sums[parts] = {};
    for (int m0 = 0; m0 < terms; m0 += kTermsPerBlock)
    {
#pragma GCC unroll 4
        for (int j = 0; j < parts; ++j)
        {
            const int m = m0 + j * lanes;
            const Block hm = loadBlock<Block>(h + m);
            Block u = washout * loadBlock<Block>(r + m) * (hm + loadBlock<Block>(w + m) * scaledFlux);
            u = flushTinyToZero(u); // keep long silences free of denormals
            storeBlock(h + m, u);
            sums[j] += u;
        }
    }
    return sumOfParts<double, lanes, parts>(sums);
}

ROSIN_KERNEL_VARIANTS_BY_WIDTH(double, advanceHistory,
                               (double* h, const double* r, const double* w, int terms, double scaledFlux,
                                double washout),
                               (h, r, w, terms, scaledFlux, washout))

double advanceHistory(double* h, const double* r, const double* w, int terms, double scaledFlux,
                      double washout) noexcept
{
    ROSIN_KERNEL_DISPATCH(kLevel, advanceHistory, (h, r, w, terms, scaledFlux, washout));
}
} // namespace

void ConductingSide::prepare(double radius, const ThermalMaterial& material, double dt)
{
    kernel_.fit(radius, material.conductivity, material.volumetricHeatCapacity, dt);
    const auto& c = kernel_.coefficients();
    const auto& tau = kernel_.timeConstants();
    const size_t M = c.size();
    const auto padded = static_cast<size_t>(paddedToWholeBlocks(static_cast<int>(M), kTermsPerBlock));
    decay_.assign(padded, 0.0);
    weight_.assign(padded, 0.0);
    history_.assign(padded, 0.0);
    for (size_t m = 0; m < M; ++m)
    {
        decay_[m] = std::exp(-dt / tau[m]);
        weight_[m] =
            -c[m] * tau[m] * std::expm1(-dt / tau[m]); // int over one step of c e^{-t/tau} per unit flux
    }
    reset();
}

void ConductingSide::reset() noexcept
{
    std::fill(history_.begin(), history_.end(), 0.0);
    historySum_ = 0.0;
}

void ConductingSide::advance(double scaledFlux, double washout) noexcept
{
    historySum_ = advanceHistory(history_.data(), decay_.data(), weight_.data(),
                                 static_cast<int>(history_.size()), scaledFlux, washout);
}

double ConductingSide::discreteSteadyResistance(double s, double d, double f) const noexcept
{
    double R = kernel_.firstStepWeight() * f;
    const auto& c = kernel_.coefficients();
    const auto& tau = kernel_.timeConstants();
    // The fitted terms only (decay_ and weight_ carry silent padding); at s = 1, r w / (1 - r) = r c tau
    // without the cancellation.
    for (size_t m = 0; m < c.size(); ++m)
        R +=
            s == 1.0 ? d * decay_[m] * c[m] * tau[m] : d * s * decay_[m] * weight_[m] / (1.0 - s * decay_[m]);
    return R;
}

} // namespace rosin::physics
