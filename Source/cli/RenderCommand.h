#pragma once
// `rosin render`: a bow gesture through one voice into a WAV of the bridge force (scaled for listening) and,
// with --probe, a 5-channel WAV of internal channels in SI units.
#include <ostream>
#include <string>
#include <vector>

#include "cli/HelpPage.h"

namespace rosin::cli
{

/// The manual of `rosin render` (its --help text and its section of the man page).
HelpPage renderHelpPage();
/// The full `rosin render --help` text.
std::string renderHelp();
/// Parses the arguments after "render" as the command would, without running it; throws as runRender.
void checkRenderArguments(const std::vector<std::string>& args);
/// Runs the subcommand with the arguments after "render". Reports to `out`; throws UsageError, ConfigError or
/// std::exception on bad input (the dispatcher prints them and chooses the exit status).
int runRender(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace rosin::cli
