#pragma once
// Spectral measurements for tests: a Hann-windowed, zero-padded FFT and an interpolated peak finder.
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <unsupported/Eigen/FFT>

namespace rosin::test
{

struct Peak
{
    double frequency = 0.0; ///< Hz, interpolated
    double magnitude = 0.0; ///< linear, interpolated
};

/// Magnitude spectrum of x[start, start+length) with a Hann window, zero-padded to `fftSize`.
inline std::vector<double> hannSpectrum(const std::vector<double>& x, std::size_t start, std::size_t length,
                                        std::size_t fftSize)
{
    std::vector<double> buf(fftSize, 0.0);
    for (std::size_t i = 0; i < length && start + i < x.size(); ++i)
        buf[i] = x[start + i] * 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * i / (length - 1)));
    Eigen::FFT<double> fft;
    std::vector<std::complex<double>> spec;
    fft.fwd(spec, buf);
    std::vector<double> mag(fftSize / 2);
    for (std::size_t i = 0; i < mag.size(); ++i)
        mag[i] = std::abs(spec[i]);
    return mag;
}

/// Largest peak of `mag` between fLo and fHi (Hz), refined by a parabola through log magnitudes.
inline Peak findPeak(const std::vector<double>& mag, double binHz, double fLo, double fHi)
{
    std::size_t lo = static_cast<std::size_t>(std::max(1.0, std::floor(fLo / binHz)));
    std::size_t hi = std::min(mag.size() - 2, static_cast<std::size_t>(std::ceil(fHi / binHz)));
    std::size_t best = lo;
    for (std::size_t i = lo; i <= hi; ++i)
        if (mag[i] > mag[best])
            best = i;
    const double a = std::log(mag[best - 1] + 1e-300), b = std::log(mag[best] + 1e-300),
                 c = std::log(mag[best + 1] + 1e-300);
    const double denom = a - 2.0 * b + c;
    const double delta = denom != 0.0 ? 0.5 * (a - c) / denom : 0.0;
    return {(best + delta) * binHz, std::exp(b - 0.25 * (a - c) * delta)};
}

inline double cents(double f, double reference)
{
    return 1200.0 * std::log2(f / reference);
}

} // namespace rosin::test
