#pragma once
// `rosin render --midi FILE.mid ...`: a MIDI file (and optional automation lanes) through the instrument's
// engine (engine::OfflineInstrument, the blocks the plugin's processor plays), into a WAV of exactly what the
// plugin would play.
#include <ostream>
#include <string>
#include <vector>

namespace rosin::cli
{

/// True if the arguments select the MIDI path (a --midi option).
bool isMidiRender(const std::vector<std::string>& args);
/// The --help section for the MIDI path.
std::string midiRenderHelp();
/// Runs it; errors as for runRender (UsageError, ConfigError, std::exception).
int runMidiRender(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace rosin::cli
