#pragma once
// rosin synth-data --generator independent: the same plan as rosin synth-data (SynthPlan: the dataset with
// its nominal settings, the trials' actual settings, the faults, the hidden effects), simulated by a second,
// independent method (IndependentTrial: waveguide string, finite-difference heat balance, own effect forms,
// own nuisance and measurement chain) so that rosin discover can be tested on data its own stepper did not
// make. Same contract as runSynthData (SynthRun.h): sets plan.dataset.sensor.noiseRms from a pilot of up to
// 8 trials (kNoiseShareOfPeak x their median peak bridge force) before the first sink call, then calls the
// sink once per trial in trial order on the calling thread with the dataset's channels. Deterministic for a
// seed, whatever the number of threads.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "lab/discovery/independent/GeneratorMember.h"
#include "lab/discovery/independent/LabChain.h"
#include "lab/discovery/independent/Nuisance.h"
#include "lab/discovery/independent/OwnEffects.h"
#include "lab/discovery/synth/SynthRun.h"

namespace rosin::discovery
{

inline constexpr const char* kIndependentGenerator = "rosin-independent/1";
/// The string is stepped at this multiple of the dataset's rate, then low-passed and decimated (the nominal
/// design's; a family member draws its own, GeneratorMember.h).
inline constexpr int kIndependentOversampling = 2;

/// What the independent generator draws for a plan, beyond the plan itself (for the truth file).
struct IndependentTruth
{
    std::uint64_t seed = 0;
    GeneratorMember member; ///< the family member (plan.generatorMember)
    Nuisance nuisance;
    OwnEffects effects;
    ChainDraw chain;
    std::vector<Channel> channels;   ///< the dataset's, to name the gains
    std::vector<double> startDelays; ///< s, per trial

    /// Flat key/value list: "generator.oversampling", "generator.member", ..., "nuisance.tension",
    /// "effect.junction-growth.gain", "chain.antiAliasCornerHz", "chain.gain.bridgeForce", ... (start delays
    /// not included).
    std::vector<std::pair<std::string, double>> values() const;
    /// {"generator", "seed", "oversampling", "member": {...}, "nuisance": {...}, "effects": {...},
    /// "chain": {...}, "startDelays": [...]}.
    nlohmann::ordered_json toJson() const;
};

/// The draws for this plan (the same ones runIndependentSynthData uses).
IndependentTruth independentTruth(const SynthPlan& plan);

/// Throws std::invalid_argument for a plan this generator cannot simulate (see rigFromPlan).
void runIndependentSynthData(SynthPlan& plan, unsigned threads, const MeasuredTrialSink& sink);

} // namespace rosin::discovery
