#pragma once
// Finds and reads "rosin-preset/1" files (Resources/docs/presets.md), validating every field.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/config/Preset.h"

namespace rosin::config
{

/// The preset folder: $ROSIN_PRESET_DIR if set and non-empty, else the installed one beside the executable
/// (InstalledData.h), else the source tree's (the build's ROSIN_PRESET_DIR).
std::string presetDirectory();
/// Names (file stems) of the *.json files in presetDirectory(), sorted.
std::vector<std::string> presetNames();
/// The file a --preset argument refers to: a value ending in ".json" or containing '/' is a path; anything
/// else is a name looked up as presetDirectory()/NAME.json. Does not check that the file exists.
std::string resolvePresetPath(const std::string& nameOrPath);
/// Reads and validates a preset. Throws ConfigError naming the file, field and expectation.
Preset loadPreset(const std::string& nameOrPath);
/// Validates an already parsed document; `file` is used in messages, `defaultName` when "name" is absent.
Preset parsePreset(const nlohmann::json& root, const std::string& file, const std::string& defaultName);

} // namespace rosin::config
