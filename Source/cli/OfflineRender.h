#pragma once
// The render loop shared by the subcommands: a prepared gesture drives a prepared voice sample by sample,
// and blocks of results go to a sink (a WAV writer, an analysis). JUCE-free.
#include <cstdint>
#include <functional>

#include "core/gesture/BowGesture.h"
#include "core/physics/voice/BowedStringVoice.h"

namespace rosin::cli
{

struct RenderStats
{
    std::int64_t samples = 0;
    double peakBridgeForce = 0.0;       ///< N, largest |bridge force|
    double maxContactTemperature = 0.0; ///< K above ambient
    int runawayRecoveries = 0;          ///< samples at which the voice reset itself after a non-finite state
    int nonFiniteSamples = 0;           ///< samples whose outputs were not finite (written as 0)
};

using VoiceSampleSink = std::function<void(const physics::VoiceSample* samples, int count)>;

/// Runs `gesture` from its start to its end through `voice` (neither is reset here), calling `sink` with
/// blocks of at most blockSize samples. Non-finite outputs are replaced by 0 before the sink sees them.
RenderStats renderGesture(physics::BowedStringVoice& voice, gesture::BowGesture& gesture,
                          const VoiceSampleSink& sink, int blockSize = 4096);

} // namespace rosin::cli
