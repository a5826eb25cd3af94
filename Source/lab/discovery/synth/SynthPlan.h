#pragma once
// What rosin synth-data will write, decided before anything is simulated: the dataset's description with the
// NOMINAL settings a laboratory would record, and, kept apart, the truth a laboratory would not know: the
// hidden effects with their values, the force and bow motion each trial actually had (the bowing machine's
// small trial-to-trial scatter), and which trials failed and how. Everything follows from the settings and
// the seed (SeededRandom streams), so the same command gives the same dataset byte for byte.
#include <cstdint>
#include <optional>
#include <vector>

#include "core/config/Preset.h"
#include "lab/discovery/Dataset.h"
#include "lab/discovery/EffectCatalog.h"
#include "lab/discovery/SimulationModel.h"
#include "lab/discovery/TrialSimulator.h"
#include "lab/discovery/synth/TrialFault.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::discovery
{

/// The measurement chain's fixed numbers ([Galluzzo2017]'s 0.5 Hz sensor high-pass, noise, jitter).
inline constexpr double kSensorHighpassHz = 0.5;
/// Noise rms as a share of the typical (median) peak bridge force of the trials.
inline constexpr double kNoiseShareOfPeak = 0.003;
/// Standard deviation of the actual bow force and acceleration (or speed) about the nominal, relative; the
/// scatter is cut at 3 standard deviations.
inline constexpr double kForceJitter = 0.015;
inline constexpr double kMotionJitter = 0.015;
/// The rig's stated ambient temperature, deg C (the thermal laws' calibration ambient).
inline constexpr double kRigAmbientCelsius = 20.0;

/// One effect to hide: per parameter a given value, or std::nullopt to draw one from the seed.
struct EffectRequest
{
    const Effect* effect = nullptr;
    std::vector<std::optional<double>> fixed;
};

struct SynthSettings
{
    /// The grid and trial protocol: kind, betas, forces, second axis (accelerations or bow speeds),
    /// trialSeconds, sampleRate (an integer). Its model is not used: the preset below is.
    scan::ScanSpec scan;
    config::Preset preset;
    std::vector<EffectRequest> effects; ///< empty: no hidden effect
    std::uint64_t seed = 0;
    bool allChannels = false; ///< also frictionForce and bowPointVelocity
    /// The independent generator's family member (independent/GeneratorMember.h; 0: its nominal design).
    unsigned generatorMember = 0;
};

struct HiddenEffect
{
    const Effect* effect = nullptr;
    std::vector<double> values; ///< in parameter order
};

struct SynthPlan
{
    /// dataset.json's content; folder empty, sensor.noiseRms unset until the run's pilot has measured the
    /// typical peak force.
    Dataset dataset;
    std::vector<TrialSettings> actual;             ///< per trial: what is simulated
    std::vector<std::optional<TrialFault>> faults; ///< per trial: how it failed (invalid trials only)
    SimulationModel model;                         ///< the preset with the hidden effects applied
    std::vector<HiddenEffect> effects;
    std::uint64_t seed = 0;
    unsigned generatorMember = 0; ///< as SynthSettings
    std::string presetName;
};

/// Plans the dataset. Throws std::invalid_argument if an effect's given value is out of range.
SynthPlan planSynthData(const SynthSettings& settings);

/// The values of one hidden effect: the given ones, the others drawn from the effect's own stream
/// (uniform, log-uniform for logarithmic parameters, random sign for signed ones; 3 significant digits).
std::vector<double> drawEffectValues(const EffectRequest& request, std::uint64_t seed);

/// Trial ids "b0899-f03-a10" (Guettler) / "b0899-f03-v00" (Schelleng): beta x 10^4, then the force and
/// motion indices. Betas too close for 4 digits get 6, then their index.
std::vector<std::string> trialIds(const scan::ScanSpec& spec);

} // namespace rosin::discovery
