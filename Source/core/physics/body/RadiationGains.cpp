#include "core/physics/body/RadiationGains.h"

#include <cmath>

namespace rosin::physics
{

double radiationGainDb(const std::vector<RadiationGainPoint>& curve, double frequencyHz) noexcept
{
    if (curve.empty())
        return 0.0;
    if (frequencyHz <= curve.front().frequencyHz)
        return curve.front().gainDb;
    for (std::size_t i = 1; i < curve.size(); ++i)
    {
        const RadiationGainPoint& a = curve[i - 1];
        const RadiationGainPoint& b = curve[i];
        if (frequencyHz <= b.frequencyHz)
        {
            const double x = std::log(frequencyHz / a.frequencyHz) / std::log(b.frequencyHz / a.frequencyHz);
            return a.gainDb + x * (b.gainDb - a.gainDb);
        }
    }
    return curve.back().gainDb;
}

void applyRadiationGains(BodyParameters& body, const std::vector<RadiationGainPoint>& curve)
{
    for (BodyMode& m : body.modes)
        m.radiationGain = std::pow(10.0, radiationGainDb(curve, m.frequency) / 20.0);
}

} // namespace rosin::physics
