#pragma once
// `rosin discover DATASET --json OUT.json --report DIR`: where a measured dataset and the model disagree,
// which effect of the catalog is missing, and the gap before and after. The engine is
// rosin::discovery (discovery/discover/, JUCE-free); this file reads the trial files, writes the outputs
// and runs the figure script.
#include <ostream>
#include <string>
#include <vector>

#include "cli/HelpPage.h"

namespace rosin::cli
{

std::string discoverHelp();
/// The manual of `rosin discover` (its --help text and its section of the man page).
HelpPage discoverHelpPage();

struct DiscoverCommandLine
{
    std::string folder;    ///< the dataset
    ParsedOptions options; ///< as the table parsed them
};
/// The arguments after "discover", parsed; UsageError without a DATASET, --json or --report (unless --help).
DiscoverCommandLine parseDiscoverCommandLine(const std::vector<std::string>& args);
/// Parses them as the command would, without running it; throws as runDiscover.
void checkDiscoverArguments(const std::vector<std::string>& args);
int runDiscover(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace rosin::cli
