#include "SensorChain.h"

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
