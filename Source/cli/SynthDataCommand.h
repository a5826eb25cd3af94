#pragma once
// `rosin synth-data`: a measured-like dataset ("rosin-measurements/1", shared/spec/measurements.md) from
// Rosin's model with physical effects hidden (the discovery workflow's test data, issue 5 item 3). The
// engine is rosin::discovery (SynthPlan, SynthRun: JUCE-free); this file is the command's help, its checks
// of the output paths, and the writing: trial files through writeTrialSignals into DIR.tmp, dataset.json
// last, then one rename, so a failed or interrupted run leaves nothing behind.
#include <ostream>
#include <string>
#include <vector>

namespace rosin::cli
{

/// The full `rosin synth-data --help` text (the effect catalog included).
std::string synthDataHelp();
/// Runs the subcommand with the arguments after "synth-data" (see Dispatcher.h for the error handling).
int runSynthData(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace rosin::cli
