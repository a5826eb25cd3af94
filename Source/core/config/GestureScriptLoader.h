#pragma once
// Reads "rosin-gesture/1" scripts (Resources/docs/gesture-script.md): timed segments of force, speed or
// acceleration, beta and finger position, each a constant or a ramp.
#include <string>

#include <nlohmann/json.hpp>

#include "core/gesture/GestureScript.h"

namespace rosin::config
{

/// Reads and validates a gesture script. `start` supplies what the first segment holds for absent
/// quantities (its beta is normally the preset's). Throws ConfigError naming the file, field and expectation.
gesture::GestureScript loadGestureScript(const std::string& path, const gesture::GestureStart& start = {});
/// Validates an already parsed document; `file` is used in messages.
gesture::GestureScript parseGestureScript(const nlohmann::json& root, const std::string& file,
                                          const gesture::GestureStart& start = {});

} // namespace rosin::config
