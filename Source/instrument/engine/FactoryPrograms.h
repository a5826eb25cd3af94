#pragma once
// The factory presets as the instrument's programs: presets/*.json, compiled into the plugin (JUCE binary
// data, FactoryPresetData) so an installed or copied bundle has them without any folder, and parsed with the
// config loader, once, off the audio thread. Should none parse there is one built-in program, the default
// preset, so a host always sees a valid program list.
#include <string>
#include <utility>
#include <vector>

#include "core/config/Preset.h"

namespace rosin::engine
{

struct FactoryProgram
{
    std::string name;
    config::Preset preset;
};

/// The program a new instance starts with.
inline constexpr const char* kDefaultProgramName = "cello-solo";

/// Every embedded preset that loads, by name; presets that fail to load are skipped (and reported on stderr).
std::vector<FactoryProgram> loadFactoryPrograms();
/// Index of `name` in `programs`, or 0.
int findProgram(const std::vector<FactoryProgram>& programs, const std::string& name);

/// The host parameters a program sets (its slow settings, so a host sees and automates them), as
/// (parameter ID, plain value). What it sets beyond them is ProgramExtras (InstrumentSetup.h) and its
/// measured body response.
/// Every program sets the player's parameters too: the lab mapping without a "player" object.
std::vector<std::pair<const char*, float>> programParameterValues(const config::Preset& preset);
/// The instrument's part of them (instrument, friction, body, ambient, beta, output level).
std::vector<std::pair<const char*, float>> instrumentParameterValues(const config::Preset& preset);

} // namespace rosin::engine
