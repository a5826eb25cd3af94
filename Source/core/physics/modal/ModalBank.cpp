#include "core/physics/modal/ModalBank.h"

#include <cmath>
#include <stdexcept>

namespace rosin::physics
{

void ModalBank::configure(const std::vector<ModeSpec>& modes, double sampleRate)
{
    if (!(sampleRate > 0.0))
        throw std::invalid_argument("ModalBank: sample rate must be positive");
    T_ = 1.0 / sampleRate;
    const auto n = modes.size();
    for (auto* v : {&pRe, &pIm, &wRe, &wIm})
        v->assign(n, ModalReal(0));
    s.assign(n, {});
    for (std::size_t i = 0; i < n; ++i)
    {
        if (!(modes[i].angularFrequency > 0.0 && modes[i].angularFrequency * T_ < M_PI))
            throw std::invalid_argument("ModalBank: mode frequency outside (0, Nyquist)");
        setPole(static_cast<int>(i), modes[i]);
    }
}

void ModalBank::retune(const ModeSpec* modes, int count) noexcept
{
    for (int i = 0; i < count && i < size(); ++i)
        setPole(i, modes[i]);
}

void ModalBank::setPole(int n, const ModeSpec& spec) noexcept
{
    const double omega = spec.angularFrequency;
    const double sigma = 0.5 * spec.lossFactor * omega;
    const double omegaD = omega * std::sqrt(std::max(1e-12, 1.0 - 0.25 * spec.lossFactor * spec.lossFactor));
    const std::complex<double> pole(-sigma, omegaD);
    const std::complex<double> p = std::exp(pole * T_);
    pRe[n] = static_cast<ModalReal>(p.real());
    pIm[n] = static_cast<ModalReal>(p.imag());
    s[n] = pole;
}

void ModalBank::reset() noexcept
{
    for (auto* v : {&wRe, &wIm})
        for (auto& x : *v)
            x = ModalReal(0);
}

std::complex<double> ModalBank::residue(int n, ModalOutput kind) const noexcept
{
    // Partial fractions of 1/((s - s1)(s - s1*)): residue r = 1/(s1 - s1*) at s1; velocity multiplies by s1,
    // acceleration by s1^2 (plus a unit direct term).
    const std::complex<double> s1 = s[n];
    const std::complex<double> r = 1.0 / (s1 - std::conj(s1));
    switch (kind)
    {
    case ModalOutput::Displacement:
        return r;
    case ModalOutput::Velocity:
        return r * s1;
    case ModalOutput::Acceleration:
        return r * s1 * s1;
    }
    return r;
}

double ModalBank::direct(int n, ModalOutput kind) const noexcept
{
    // H(1) = 2 Re(rho p T / (1 - p)) + D must equal the continuous DC gain.
    const std::complex<double> p(pRe[n], pIm[n]);
    const double dcTrue = kind == ModalOutput::Displacement ? 1.0 / std::norm(s[n]) : 0.0;
    return dcTrue - 2.0 * (residue(n, kind) * p * T_ / (1.0 - p)).real();
}

double ModalBank::modalStiffness(int n) const noexcept
{
    return std::norm(s[n]);
}

double ModalBank::outputAtLastStep(int n, ModalOutput kind, double x) const noexcept
{
    // w~[k+1] = p (w~[k] + T x[k])  =>  w~[k] = w~[k+1] / p - T x[k].
    const std::complex<double> p(pRe[n], pIm[n]);
    const std::complex<double> w = std::complex<double>(wRe[n], wIm[n]) / p - T_ * x;
    return 2.0 * (residue(n, kind) * w).real() + direct(n, kind) * x;
}

double ModalBank::value(int n, ModalOutput kind, double x) const noexcept
{
    const std::complex<double> w(wRe[n], wIm[n]);
    return 2.0 * (residue(n, kind) * w).real() + direct(n, kind) * x;
}

} // namespace rosin::physics
