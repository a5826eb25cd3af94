#pragma once
// `rosin COMMAND ...`: finds the subcommand, runs it, and turns every error into a message on `err` and an
// exit status, so no bad input ends in a crash. Main.cpp only forwards argv here; tests call it directly.
#include <ostream>
#include <string>
#include <vector>

namespace rosin::cli
{

/// The `rosin --help` text.
std::string usage();
/// args excludes the program name. Returns the process exit status (see ExitStatus in CommandLine.h).
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace rosin::cli
