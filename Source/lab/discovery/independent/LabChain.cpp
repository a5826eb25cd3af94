#include "lab/discovery/independent/LabChain.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lab/discovery/independent/IndependentStreams.h"

namespace rosin::discovery
{

namespace
{
// One bilinear low-pass biquad of quality q at the pre-warped corner, transposed direct form II.
void lowPassBiquad(std::vector<double>& x, double cornerHz, double sampleRate, double q)
{
    const double k = std::tan(std::numbers::pi * cornerHz / sampleRate);
    const double norm = 1.0 / (1.0 + k / q + k * k);
    const double b0 = k * k * norm, b1 = 2.0 * b0, b2 = b0;
    const double a1 = 2.0 * (k * k - 1.0) * norm, a2 = (1.0 - k / q + k * k) * norm;
    double z1 = 0.0, z2 = 0.0;
    for (double& v : x)
    {
        const double y = b0 * v + z1;
        z1 = b1 * v - a1 * y + z2;
        z2 = b2 * v - a2 * y;
        v = y;
    }
}
} // namespace

ChainDraw drawChain(std::uint64_t seed, std::size_t channels, double sampleRate)
{
    SeededRandom r(seed, independent_streams::kChain);
    ChainDraw d;
    const double scale = sampleRate / 44100.0;
    d.cornerHz = r.uniform(8000.0, 16000.0) * scale;
    for (std::size_t c = 0; c < channels; ++c)
        d.gains.push_back(r.uniform(1.0 - kGainTolerance, 1.0 + kGainTolerance));
    return d;
}

double drawStartDelay(std::uint64_t seed, std::size_t trial)
{
    SeededRandom r(seed, independent_streams::kStartDelay, trial);
    return r.uniform(0.0, kMaxStartDelay);
}

std::vector<std::pair<std::string, double>> ChainDraw::values(const std::vector<Channel>& channels) const
{
    std::vector<std::pair<std::string, double>> v{{"antiAliasCornerHz", cornerHz}};
    for (std::size_t c = 0; c < gains.size() && c < channels.size(); ++c)
        v.push_back({"gain." + channels[c].name, gains[c]});
    return v;
}

void antiAliasLowPass(std::vector<double>& x, double cornerHz, double sampleRate, int order)
{
    // Pole pair k at the angle (2k + 1) pi / (2 order) from the imaginary axis, q = 1 / (2 cos): for the 4th
    // order pi/8 and 3 pi/8.
    for (int k = 0; k < order / 2; ++k)
    {
        const double angle =
            static_cast<double>(2 * k + 1) * std::numbers::pi / static_cast<double>(2 * order);
        lowPassBiquad(x, cornerHz, sampleRate, 1.0 / (2.0 * std::cos(angle)));
    }
}

void firstOrderHighPassBilinear(std::vector<double>& x, double cornerHz, double sampleRate)
{
    const double k = std::tan(std::numbers::pi * cornerHz / sampleRate);
    const double b = 1.0 / (1.0 + k), a = (1.0 - k) / (1.0 + k);
    double previousIn = 0.0, previousOut = 0.0;
    for (double& v : x)
    {
        const double y = b * (v - previousIn) + a * previousOut;
        previousIn = v;
        previousOut = y;
        v = y;
    }
}

std::vector<double> acquire(const std::vector<double>& internal, double internalRate, double delay,
                            double cornerHz, double gain, int decimation, int order)
{
    const auto shift = static_cast<std::size_t>(std::llround(delay * internalRate));
    std::vector<double> x(internal.size(), 0.0);
    for (std::size_t i = shift; i < x.size(); ++i)
        x[i] = internal[i - shift];
    antiAliasLowPass(x, cornerHz, internalRate, order);
    const auto step = static_cast<std::size_t>(std::max(1, decimation));
    std::vector<double> out;
    out.reserve(x.size() / step);
    for (std::size_t i = 0; i < x.size(); i += step)
        out.push_back(gain * x[i]);
    return out;
}

} // namespace rosin::discovery
