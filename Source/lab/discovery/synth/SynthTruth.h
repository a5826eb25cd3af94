#pragma once
// The truth behind a synthetic dataset, which the dataset itself must not contain: the hidden effects and
// their values, the settings each trial really had (the jitter) and how the failed trials failed. rosin
// synth-data prints the effects and writes all of it to a --truth file outside the dataset folder, for
// tests and for scoring rosin discover; the discovery workflow never reads it.
#include <string>

#include <nlohmann/json.hpp>

#include "lab/discovery/synth/SynthPlan.h"

namespace rosin::discovery
{

inline constexpr const char* kTruthFormat = "rosin-synth-truth/1";

/// {"format", "dataset", "seed", "preset", "effects": [{"name", "parameters": {...}}], "sensor",
///  "jitter": {"force", "motion"}, "trials": [{"id", "bowForce", "acceleration"|"speed", "fault"?}]}
/// (actual values; the nominal ones are in dataset.json).
nlohmann::ordered_json truthJson(const SynthPlan& plan, const std::string& datasetFolder);

/// The hidden effects on one line, "; " between them ("junction-growth: growth = 0.213, onsetTime =
/// 0.00537 s; hertz-contact"), or "none".
std::string describeHiddenEffects(const SynthPlan& plan);

} // namespace rosin::discovery
