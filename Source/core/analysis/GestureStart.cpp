#include "core/analysis/GestureStart.h"

#include <cmath>

#include "core/analysis/LineFit.h"

namespace rosin::analysis
{

std::optional<double> gestureStartFromBowVelocity(const std::vector<double>& v, const GestureStartOptions& o)
{
    if (!(o.sampleRate > 0.0) || !(o.acceleration > 0.0))
        return std::nullopt;
    const auto begin = static_cast<std::size_t>(std::ceil(o.skipSeconds * o.sampleRate));
    if (v.size() < begin + 16)
        return std::nullopt;
    const double n = static_cast<double>(v.size() - begin);
    if (o.noiseRms > 0.0 && 2.0 * o.noiseRms / (o.acceleration * std::sqrt(n)) > o.maxStandardError)
        return std::nullopt;
    const LineFit line = fitLine(v, begin, v.size());
    const double slope = line.slope * o.sampleRate; // m/s^2
    if (!(std::abs(slope - o.acceleration) <= o.slopeTolerance * o.acceleration))
        return std::nullopt;
    const double t0 = (line.centre - line.mean / line.slope) / o.sampleRate;
    if (!(t0 > -o.maxStart && t0 < o.maxStart))
        return std::nullopt;
    return t0;
}

} // namespace rosin::analysis
