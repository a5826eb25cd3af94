#include "core/analysis/HarmonicTilt.h"

#include <cmath>
#include <complex>
#include <numbers>

#include <unsupported/Eigen/FFT>

namespace rosin::analysis
{

namespace
{
std::size_t nextPowerOfTwo(std::size_t n)
{
    std::size_t p = 1;
    while (p < n)
        p <<= 1;
    return p;
}

double bandPower(const std::vector<std::complex<double>>& spectrum, double binHz, double fromHz, double toHz)
{
    const auto lo = static_cast<std::size_t>(std::ceil(fromHz / binHz));
    const auto hi = std::min(spectrum.size() / 2, static_cast<std::size_t>(std::floor(toHz / binHz)));
    double sum = 0.0;
    for (std::size_t k = lo; k <= hi; ++k)
        sum += std::norm(spectrum[k]);
    return sum;
}
} // namespace

std::optional<double> harmonicTiltDb(const std::vector<double>& signal, std::size_t start, std::size_t end,
                                     const HarmonicTiltOptions& o)
{
    end = std::min(end, signal.size());
    const double f0 = o.fundamentalHz;
    if (start >= end || !(f0 > 0.0) || (o.highLast + 0.5) * f0 >= 0.5 * o.sampleRate)
        return std::nullopt;
    const std::size_t length = end - start;
    if (static_cast<double>(length) < 4.0 * o.sampleRate / f0)
        return std::nullopt;
    // Remove the mean and a linear trend first: the bow's acceleration makes the sawtooth's mean drift, and
    // a ramp leaks into the low band through the window's sidelobes.
    double sumT = 0, sumX = 0, sumTT = 0, sumTX = 0;
    for (std::size_t i = 0; i < length; ++i)
    {
        const double t = static_cast<double>(i), x = signal[start + i];
        sumT += t, sumX += x, sumTT += t * t, sumTX += t * x;
    }
    const double n = static_cast<double>(length);
    const double slope = (n * sumTX - sumT * sumX) / (n * sumTT - sumT * sumT);
    const double offset = (sumX - slope * sumT) / n;
    std::vector<double> buffer(nextPowerOfTwo(2 * length), 0.0);
    for (std::size_t i = 0; i < length; ++i)
    {
        const double w = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / (n - 1.0)));
        buffer[i] = w * (signal[start + i] - offset - slope * static_cast<double>(i));
    }
    Eigen::FFT<double> fft;
    std::vector<std::complex<double>> spectrum;
    fft.fwd(spectrum, buffer);
    const double binHz = o.sampleRate / static_cast<double>(buffer.size());
    const double low = bandPower(spectrum, binHz, (o.lowFirst - 0.5) * f0, (o.lowLast + 0.5) * f0);
    const double high = bandPower(spectrum, binHz, (o.highFirst - 0.5) * f0, (o.highLast + 0.5) * f0);
    if (!(low > 0.0) || !(high > 0.0))
        return std::nullopt;
    return 10.0 * std::log10(high / low);
}

} // namespace rosin::analysis
