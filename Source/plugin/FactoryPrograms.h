#pragma once
// The factory presets (presets/*.json, read with the config loader) as the plugin's programs. Read once, off
// the audio thread. If the folder is missing (a plugin copied to another machine) there is one built-in
// program, the default preset, so a host always sees a valid program list.
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

/// Every preset that loads; presets that fail to load are skipped (and reported on stderr).
std::vector<FactoryProgram> loadFactoryPrograms();
/// Index of `name` in `programs`, or 0.
int findProgram(const std::vector<FactoryProgram>& programs, const std::string& name);

} // namespace rosin::plugin
