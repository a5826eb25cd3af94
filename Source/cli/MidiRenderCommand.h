#pragma once
// `rosin render --midi FILE.mid ...`: a MIDI file (and optional automation lanes) through the instrument's
// engine (engine::OfflineInstrument, the blocks the plugin's processor plays), into a WAV of exactly what the
// plugin would play.
#include <ostream>
#include <string>
#include <vector>

#include "cli/HelpPage.h"

namespace rosin::cli
{

/// True if the arguments select the MIDI path (a --midi option).
bool isMidiRender(const std::vector<std::string>& args);
/// The MIDI path's usage form and its section of `rosin render --help`.
std::string midiRenderUsage();
HelpSection midiRenderSection();
/// Parses the MIDI path's arguments without running it; throws as runMidiRender.
void checkMidiRenderArguments(const std::vector<std::string>& args);
/// Runs it; errors as for runRender (UsageError, ConfigError, std::exception).
int runMidiRender(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace rosin::cli
