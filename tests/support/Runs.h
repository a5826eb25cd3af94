#pragma once
// Small drivers shared by the physics tests: steady and constant-acceleration bowing of one voice, with the
// per-sample outputs kept for analysis.
#include <algorithm>
#include <memory>
#include <vector>

#include "physics/voice/BowedStringVoice.h"

namespace rosin::test
{

struct Trace
{
    double sampleRate = 48000.0;
    std::vector<physics::VoiceSample> samples;
};

/// Bow at constant speed `speed` (m/s) with force `force` (N) at `beta` for `seconds`, reaching the speed by a
/// linear ramp over `rampSeconds` (a player's or a bowing machine's start; an instantaneous step is not).
inline Trace bowSteady(const physics::VoiceConfig& cfg, std::unique_ptr<physics::FrictionLaw> law, double fs,
                       double force, double speed, double beta, double seconds, double rampSeconds = 0.1)
{
    physics::BowedStringVoice voice;
    voice.prepare(cfg, std::move(law), fs);
    Trace t{fs, {}};
    const auto n = static_cast<std::size_t>(seconds * fs);
    t.samples.reserve(n);
    for (std::size_t k = 0; k < n; ++k)
    {
        const double ramp = rampSeconds > 0.0 ? std::min(1.0, static_cast<double>(k) / (rampSeconds * fs)) : 1.0;
        t.samples.push_back(voice.step({force, speed * ramp, beta, 1.0}));
    }
    return t;
}

/// Bow from rest with constant acceleration `accel` (m/s^2).
inline Trace bowAccelerating(const physics::VoiceConfig& cfg, std::unique_ptr<physics::FrictionLaw> law, double fs,
                             double force, double accel, double beta, double seconds)
{
    physics::BowedStringVoice voice;
    voice.prepare(cfg, std::move(law), fs);
    Trace t{fs, {}};
    const auto n = static_cast<std::size_t>(seconds * fs);
    for (std::size_t k = 0; k < n; ++k)
        t.samples.push_back(voice.step({force, accel * static_cast<double>(k) / fs, beta, 1.0}));
    return t;
}

/// Times (s) at which slipping starts (stick -> slip transitions) in [fromSeconds, end).
inline std::vector<double> slipOnsets(const Trace& t, double fromSeconds = 0.0)
{
    std::vector<double> onsets;
    for (std::size_t k = 1; k < t.samples.size(); ++k)
        if (t.samples[k - 1].sticking && !t.samples[k].sticking && k / t.sampleRate >= fromSeconds)
            onsets.push_back(k / t.sampleRate);
    return onsets;
}

/// Time of the first slip, or -1.
inline double firstSlipTime(const Trace& t)
{
    for (std::size_t k = 0; k < t.samples.size(); ++k)
        if (!t.samples[k].sticking)
            return k / t.sampleRate;
    return -1.0;
}

} // namespace rosin::test
