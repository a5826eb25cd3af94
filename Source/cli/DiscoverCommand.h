#pragma once
// `rosin discover DATASET --json OUT.json --report DIR`: where a measured dataset and the model disagree,
// which effect of the catalog is missing, and the gap before and after (issue 5 item 1). The engine is
// rosin::discovery (discovery/discover/, JUCE-free); this file reads the trial files, writes the outputs
// and runs the figure script.
#include <ostream>
#include <string>
#include <vector>

namespace rosin::cli
{

std::string discoverHelp();
int runDiscover(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace rosin::cli
