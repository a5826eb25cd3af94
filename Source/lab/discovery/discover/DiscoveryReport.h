#pragma once
// rosin discover's outputs: OUT.json (the schema of discover.md) and the researcher's report in Markdown.
//   { "dataset", "trialsUsed", "trialsSkipped", "maxEffects", "baseline": {friction, contact, body, string},
//     "gapBefore", "features": [{name, unit, scatter, scatterMethod, trials, gapBefore, gapAfter, where,
//     whereAfter}], "steps": [{effect, parameters{}, gapAfter, heldOutGain, pValue, evidence, tried[]}],
//     "gapAfter", "status", "verdict" (= status), "gapDefinition", "seconds" }
// JUCE-free.
#include <string>

#include <nlohmann/json.hpp>

#include "lab/discovery/discover/Discovery.h"

namespace rosin::discovery
{

nlohmann::json discoveryJson(const Discovery& d, const Dataset& dataset);

/// The report; `figures` lists PNG file names (relative to the report) to embed, may be empty.
std::string discoveryMarkdown(const Discovery& d, const Dataset& dataset,
                              const std::vector<std::string>& figures);

/// Per-trial features (measured, baseline, final) with the grid coordinates, for the figure script.
nlohmann::json discoveryMaps(const Discovery& d, const Dataset& dataset);

} // namespace rosin::discovery
