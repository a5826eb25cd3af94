#pragma once
// `rosin scan compare A B --out DIR`: the difference of two finished scans of the same kind and grid, as a
// figure in the style of [Galluzzo2017] Figs. 9-11 (what a model variation changes), drawn by the lab's
// figure script, and the Helmholtz share of each printed.
#include <ostream>
#include <string>
#include <vector>

#include "cli/OptionTable.h"

namespace rosin::cli
{

struct ScanComparison
{
    std::vector<std::string> folders; ///< the two finished scans
    std::string out;                  ///< the folder of the figure
};

/// The options of `rosin scan compare` (for its help, the man page and the completion).
const OptionTable& scanCompareOptionTable();
/// args after "compare", parsed; UsageError unless two folders and --out are given.
ScanComparison parseScanCompare(const std::vector<std::string>& args);

/// args after "compare". Returns the exit status; throws UsageError / scan::ScanError on bad input.
int runScanCompare(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace rosin::cli
