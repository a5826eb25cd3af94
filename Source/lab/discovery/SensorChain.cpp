#include "lab/discovery/SensorChain.h"

#include <numbers>

namespace rosin::discovery
{

bool passesSensorHighPass(const Channel& channel)
{
    return channel.unit == "N";
}

void firstOrderHighPass(std::vector<double>& signal, double cutoffHz, double sampleRate)
{
    const double a = 1.0 / (1.0 + 2.0 * std::numbers::pi * cutoffHz / sampleRate);
    double previousIn = 0.0, previousOut = 0.0;
    for (double& x : signal)
    {
        const double y = a * (previousOut + x - previousIn);
        previousIn = x;
        previousOut = y;
        x = y;
    }
}

void butterworthLowPass(std::vector<double>& signal, double cornerHz, double sampleRate)
{
    // Bilinear transform with the corner pre-warped (RBJ's cookbook form, Q = 1/sqrt 2), from rest.
    const double w = 2.0 * std::numbers::pi * cornerHz / sampleRate;
    const double alpha = std::sin(w) / std::numbers::sqrt2, c = std::cos(w), a0 = 1.0 + alpha;
    const double b0 = 0.5 * (1.0 - c) / a0, b1 = (1.0 - c) / a0, a1 = -2.0 * c / a0, a2 = (1.0 - alpha) / a0;
    double x1 = 0.0, x2 = 0.0, y1 = 0.0, y2 = 0.0;
    for (double& x : signal)
    {
        const double y = b0 * (x + x2) + b1 * x1 - a1 * y1 - a2 * y2;
        x2 = x1, x1 = x, y2 = y1, y1 = y;
        x = y;
    }
}

void applyGaugeCalibration(const std::vector<Channel>& layout, std::vector<std::vector<double>>& channels,
                           double gain, double lowpassHz, double sampleRate)
{
    for (std::size_t c = 0; c < layout.size() && c < channels.size(); ++c)
    {
        if (!passesSensorHighPass(layout[c]))
            continue;
        if (gain != 1.0)
            for (double& x : channels[c])
                x *= gain;
        if (lowpassHz > 0.0)
            butterworthLowPass(channels[c], lowpassHz, sampleRate);
    }
}

void applySensorResponse(const std::vector<Channel>& layout, std::vector<std::vector<double>>& channels,
                         const Sensor& sensor, double sampleRate)
{
    if (!sensor.highpassHz || !(*sensor.highpassHz > 0.0))
        return;
    for (std::size_t c = 0; c < layout.size() && c < channels.size(); ++c)
        if (passesSensorHighPass(layout[c]))
            firstOrderHighPass(channels[c], *sensor.highpassHz, sampleRate);
}

void addSensorNoise(std::vector<std::vector<double>>& channels, const Sensor& sensor, SeededRandom& random)
{
    if (!sensor.noiseRms || !(*sensor.noiseRms > 0.0))
        return;
    for (auto& channel : channels)
        for (double& x : channel)
            x += *sensor.noiseRms * random.normal();
}

} // namespace rosin::discovery
