// One solid's conduction memory (ConductingSide.h; reference eq. 2.9 with the washout of §2.3a).
#include "ConductingSide.h"

#include <algorithm>
#include <cmath>

namespace rosin::physics
{

void ConductingSide::prepare(double radius, const ThermalMaterial& material, double dt)
{
    kernel_.fit(radius, material.conductivity, material.volumetricHeatCapacity, dt);
    const auto& c = kernel_.coefficients();
    const auto& tau = kernel_.timeConstants();
    const size_t M = c.size();
    decay_.resize(M);
    weight_.resize(M);
    history_.assign(M, 0.0);
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
    double sum = 0.0;
    double* __restrict h = history_.data();
    const double* __restrict r = decay_.data();
    const double* __restrict w = weight_.data();
    const int M = static_cast<int>(history_.size());
#pragma omp simd reduction(+ : sum)
    for (int m = 0; m < M; ++m)
    {
        double u = washout * r[m] * (h[m] + w[m] * scaledFlux);
        u = std::abs(u) < 1e-250 ? 0.0 : u; // keep long silences free of denormals
        h[m] = u;
        sum += u;
    }
    historySum_ = sum;
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
