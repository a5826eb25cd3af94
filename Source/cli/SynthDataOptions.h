#pragma once
// The command line of `rosin synth-data`, checked before anything is simulated or written: a bad value throws
// config::ConfigError naming the option, the value and what was expected (exit status 1), a wrong shape
// UsageError (exit status 2). The grid and trial options are rosin scan's own, parsed by its parser, so the
// two commands accept and reject exactly the same grids.
#include <optional>
#include <string>
#include <vector>

#include "cli/OptionTable.h"
#include "lab/discovery/synth/SynthPlan.h"

namespace rosin::cli
{

struct SynthDataCommandLine
{
    bool help = false;
    discovery::SynthSettings settings;
    std::string out;                  ///< the dataset folder
    std::optional<std::string> truth; ///< --truth FILE
    unsigned threads = 0;             ///< 0: every core
    /// --generator: "rosin" (Rosin's own stepper) or "independent" (discovery/independent: a waveguide
    /// string with its own heat balance, effect forms, nuisance draws and measurement chain).
    std::string generator = "rosin";
};

/// The options of `rosin synth-data` (parsing and --help).
const OptionTable& synthDataOptionTable();

/// args: everything after "synth-data".
SynthDataCommandLine parseSynthDataCommandLine(const std::vector<std::string>& args);

/// Defaults that differ from rosin scan's: a dataset is smaller than a diagram.
inline constexpr const char* kSynthDefaultDuration = "0.4";
inline constexpr const char* kSynthDefaultSampleRate = "44100";
inline constexpr const char* kSynthDefaultGrid = "10";
inline constexpr const char* kSynthDefaultBeta = "0.0899";
/// Shortest trial: a first slip and a few periods must fit.
inline constexpr double kSynthMinDuration = 0.01;

} // namespace rosin::cli
