#pragma once
// `rosin scan schelleng|guettler|merge`: playability diagrams of one string ([Galluzzo2017]
// sections 3.1-3.3), computed on every core, resumable, splittable into shards or over MPI ranks, with the
// same files whatever the split. The engine is rosin::scan (Source/lab/scan/); this file is the command's
// help and its run.
#include <ostream>
#include <string>
#include <vector>

#include "cli/HelpPage.h"

namespace rosin::cli
{

/// The manual of `rosin scan` (its --help text and its section of the man page).
HelpPage scanHelpPage();
/// The full `rosin scan --help` text.
std::string scanHelp();
/// Parses the arguments after "scan" as the command would, without running it; throws as runScan.
void checkScanArguments(const std::vector<std::string>& args);
/// Runs the subcommand with the arguments after "scan" (see Dispatcher.h for the error handling).
int runScan(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace rosin::cli
