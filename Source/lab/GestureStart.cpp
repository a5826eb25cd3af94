#include "GestureStart.h"

#include <cmath>

namespace rosin::lab
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
    // Least-squares line v = p + q t over the window, with t centred for a well-conditioned sum.
    const double tMean =
        (static_cast<double>(begin) + static_cast<double>(v.size() - 1)) / 2.0 / o.sampleRate;
    double sv = 0.0, stv = 0.0, stt = 0.0;
    for (std::size_t k = begin; k < v.size(); ++k)
    {
        const double t = static_cast<double>(k) / o.sampleRate - tMean;
        sv += v[k];
        stv += t * v[k];
        stt += t * t;
    }
    const double slope = stv / stt;
    const double meanV = sv / n;
    if (!(std::abs(slope - o.acceleration) <= o.slopeTolerance * o.acceleration))
        return std::nullopt;
    const double t0 = tMean - meanV / slope;
    if (!(t0 > -o.maxStart && t0 < o.maxStart))
        return std::nullopt;
    return t0;
}

} // namespace rosin::lab
