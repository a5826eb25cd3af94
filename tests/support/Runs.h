#pragma once
// Small drivers shared by the physics tests: steady and constant-acceleration bowing of one voice, with the
// per-sample outputs kept for analysis.
#include <algorithm>
#include <memory>
#include <vector>

#include "core/physics/voice/BowedStringVoice.h"

namespace rosin::test
{

struct Trace
{
    double sampleRate = 48000.0;
    std::vector<physics::VoiceSample> samples;
};

/// Bow at constant speed `speed` (m/s) with force `force` (N) at `beta` for `seconds`, reaching the speed by
/// a linear ramp over `rampSeconds` (a player's or a bowing machine's start; an instantaneous step is not).
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
        const double ramp =
            rampSeconds > 0.0 ? std::min(1.0, static_cast<double>(k) / (rampSeconds * fs)) : 1.0;
        t.samples.push_back(voice.step({force, speed * ramp, beta, 1.0}));
    }
    return t;
}

/// Bow from rest with constant acceleration `accel` (m/s^2).
inline Trace bowAccelerating(const physics::VoiceConfig& cfg, std::unique_ptr<physics::FrictionLaw> law,
                             double fs, double force, double accel, double beta, double seconds)
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

/// One maximal run of sliding samples.
struct SlipEpisode
{
    double start = 0.0;            ///< s
    double duration = 0.0;         ///< s
    double peakSpeed = 0.0;        ///< largest |v - v_b| in the episode, m/s
    double bowSpeed = 0.0;         ///< |v_b| at the start, m/s
    double backwardDuration = 0.0; ///< s during which the string moved backwards (|v - v_b| > |v_b|)
    /// A flyback: the string moves backwards (|v - v_b| > |v_b|), the slip of Helmholtz motion. Shorter
    /// partial slips, in which the string only lags the bow, are not flybacks.
    bool flyback() const { return peakSpeed > bowSpeed; }
};

/// Slip episodes starting at or after fromSeconds.
inline std::vector<SlipEpisode> slipEpisodes(const Trace& t, double fromSeconds = 0.0)
{
    std::vector<SlipEpisode> episodes;
    for (std::size_t k = 1; k < t.samples.size(); ++k)
    {
        const auto& s = t.samples[k];
        const bool starts = t.samples[k - 1].sticking && !s.sticking;
        if (starts && k / t.sampleRate >= fromSeconds)
            episodes.push_back({k / t.sampleRate, 0.0, 0.0, std::abs(s.bowVelocity)});
        if (!s.sticking && !episodes.empty() && k / t.sampleRate >= episodes.back().start)
        {
            auto& e = episodes.back();
            e.duration = (k + 1) / t.sampleRate - e.start;
            const double slide = std::abs(s.bowPointVelocity - s.bowVelocity);
            e.peakSpeed = std::max(e.peakSpeed, slide);
            if (slide > std::abs(s.bowVelocity))
                e.backwardDuration += 1.0 / t.sampleRate;
        }
    }
    return episodes;
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
