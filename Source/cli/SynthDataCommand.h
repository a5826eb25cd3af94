#pragma once
// `rosin synth-data`: a measured-like dataset ("rosin-measurements/1", Resources/docs/measurements.md) from
// Rosin's model with physical effects hidden (the discovery workflow's test data). The
// engine is rosin::discovery (SynthPlan, SynthRun: JUCE-free); this file is the command's help, its checks
// of the output paths, and the writing: trial files through writeTrialSignals into DIR.tmp, dataset.json
// last, then one rename, so a failed or interrupted run leaves nothing behind.
#include <ostream>
#include <string>
#include <vector>

#include "cli/HelpPage.h"

namespace rosin::cli
{

/// The full `rosin synth-data --help` text (the effect catalog included).
std::string synthDataHelp();
/// The manual of `rosin synth-data` (its --help text and its section of the man page).
HelpPage synthDataHelpPage();
/// Parses the arguments after "synth-data" as the command would, without running it; throws as runSynthData.
void checkSynthDataArguments(const std::vector<std::string>& args);
/// Runs the subcommand with the arguments after "synth-data" (see Dispatcher.h for the error handling).
int runSynthData(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace rosin::cli
