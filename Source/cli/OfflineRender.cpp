#include "cli/OfflineRender.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rosin::cli
{

namespace
{
// Keeps a file readable if the physics ever produced a NaN or inf; the stats report it.
bool sanitise(physics::VoiceSample& s)
{
    bool clean = true;
    for (double* v :
         {&s.bridgeForce, &s.bowPointVelocity, &s.frictionForce, &s.bowVelocity, &s.contactTemperature})
        if (!std::isfinite(*v))
        {
            *v = 0.0;
            clean = false;
        }
    return clean;
}
} // namespace

RenderStats renderGesture(physics::BowedStringVoice& voice, gesture::BowGesture& gesture,
                          const VoiceSampleSink& sink, int blockSize)
{
    RenderStats stats;
    std::vector<physics::VoiceSample> block(static_cast<std::size_t>(std::max(1, blockSize)));
    while (!gesture.finished())
    {
        const auto remaining = gesture.totalSamples() - gesture.position();
        const int count =
            static_cast<int>(std::min<std::int64_t>(remaining, static_cast<std::int64_t>(block.size())));
        for (int i = 0; i < count; ++i)
        {
            physics::VoiceSample s = voice.step(gesture.next());
            if (voice.recoveredFromRunaway())
                ++stats.runawayRecoveries;
            if (!sanitise(s))
                ++stats.nonFiniteSamples;
            stats.peakBridgeForce = std::max(stats.peakBridgeForce, std::abs(s.bridgeForce));
            stats.maxContactTemperature = std::max(stats.maxContactTemperature, s.contactTemperature);
            block[static_cast<std::size_t>(i)] = s;
        }
        stats.samples += count;
        sink(block.data(), count);
    }
    return stats;
}

} // namespace rosin::cli
