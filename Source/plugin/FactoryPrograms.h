#pragma once
// The factory presets as the plugin's programs: presets/*.json, compiled into the plugin (JUCE binary data,
// FactoryPresetData) so an installed or copied bundle has them without any folder, and parsed with the config
// loader, once, off the audio thread. Should none parse there is one built-in program, the default preset, so
// a host always sees a valid program list.
#include <string>
#include <vector>

#include "config/Preset.h"

namespace rosin::plugin
{

struct FactoryProgram
{
    std::string name;
    config::Preset preset;
};

/// Every embedded preset that loads, by name; presets that fail to load are skipped (and reported on stderr).
std::vector<FactoryProgram> loadFactoryPrograms();
/// Index of `name` in `programs`, or 0.
int findProgram(const std::vector<FactoryProgram>& programs, const std::string& name);

} // namespace rosin::plugin
