// One solid's conduction memory (ConductingSide.h; reference eq. 2.9 with the washout of §2.3a).
#include "ConductingSide.h"

#include <algorithm>
#include <cmath>

#include "../modal/KernelDispatch.h"
#include "../modal/VectorBlock.h"

namespace rosin::physics
{

namespace
{
const SimdLevel kLevel = simdLevel();

// kTermsPerBlock terms as one value (VectorBlock.h); prepare() pads the terms to whole blocks with silent
// ones (zero decay and weight).
constexpr int kTermsPerBlock = 8;
using TermBlock = VectorBlock<double, kTermsPerBlock>;

// Adding and removing 2^-780 (~1.6e-235) leaves every term above ~4e-219 exactly as it is, rounds smaller
// ones to multiples of 2^-832 (~3.5e-251) and sends those below half of that to zero: a decaying term leaves
// the normal range through zero, never through the slow denormals, without a compare in the vector loop.
constexpr double kFlushOffset = 0x1p-780;

ROSIN_KERNEL_BODY double advanceHistoryBody(double* __restrict h, const double* __restrict r,
                                            const double* __restrict w, int terms, double scaledFlux,
                                            double washout) noexcept
{
    TermBlock sum = {};
    for (int m = 0; m < terms; m += kTermsPerBlock)
    {
        const TermBlock hm = loadBlock<TermBlock>(h + m);
        TermBlock u = washout * loadBlock<TermBlock>(r + m) * (hm + loadBlock<TermBlock>(w + m) * scaledFlux);
        u = (u + kFlushOffset) - kFlushOffset; // keep long silences free of denormals
        storeBlock(h + m, u);
        sum += u;
    }
    return sumOfLanes<double, kTermsPerBlock>(sum);
}

ROSIN_KERNEL_VARIANTS(double, advanceHistory,
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
    const size_t padded = (M + kTermsPerBlock - 1) / kTermsPerBlock * kTermsPerBlock;
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
    for (size_t m = 0; m < decay_.size(); ++m) // at s = 1, r w / (1 - r) = r c tau without the cancellation
        R +=
            s == 1.0 ? d * decay_[m] * c[m] * tau[m] : d * s * decay_[m] * weight_[m] / (1.0 - s * decay_[m]);
    return R;
}

} // namespace rosin::physics
