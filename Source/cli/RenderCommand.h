#pragma once
// `rosin render`: a bow gesture through one voice into a WAV of the bridge force (scaled for listening) and,
// with --probe, a 5-channel WAV of internal channels in SI units.
#include <ostream>
#include <string>
#include <vector>

namespace rosin::cli
{

/// The full `rosin render --help` text.
std::string renderHelp();
/// Runs the subcommand with the arguments after "render". Reports to `out`; throws UsageError, ConfigError or
/// std::exception on bad input (the dispatcher prints them and chooses the exit status).
int runRender(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace rosin::cli
