#pragma once
// The command line of `rosin scan`, turned into a scan specification and run options. Every value is checked
// here, before anything is computed or written: a bad one throws config::ConfigError naming the option, the
// value and what was expected (exit status 1); a wrong shape throws UsageError (exit status 2).
#include <string>
#include <vector>

#include "cli/OptionTable.h"
#include "lab/scan/ScanRun.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::cli
{

struct ScanCommandLine
{
    enum class Action
    {
        Scan,
        Merge,
        Help
    };
    Action action = Action::Help;
    scan::ScanSpec spec;
    std::string out; ///< the output folder (Scan) or the folder to merge (Merge)
    scan::RunOptions run;
    bool mpi = false;
};

/// The options of `rosin scan schelleng|guettler` (parsing and --help).
const OptionTable& scanOptionTable();

/// args: everything after "scan".
ScanCommandLine parseScanCommandLine(const std::vector<std::string>& args);

/// Largest grid side (force, beta or acceleration count).
inline constexpr std::size_t kMaxGridSide = 300;

} // namespace rosin::cli
