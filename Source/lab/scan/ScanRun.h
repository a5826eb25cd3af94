#pragma once
// One run of a scan in this process: every cell, or one shard's. Resumes from the run's partial file (or
// reads back a finished run of the same specification and only writes its outputs again),
// computes the missing cells on all threads, appends each row as it finishes, and when the last cell is done
// writes the run's sorted rows (a shard) or the final files (ScanOutput.h) and removes the partial file. A
// stop request (StopSignal.h) lets the running cells finish and leaves the partial file for the next run.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>

#include "lab/scan/RunFiles.h"
#include "lab/scan/ScanOutput.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

struct RunOptions
{
    unsigned threads = 0; ///< 0: defaultThreadCount()
    std::optional<ShardId> shard;
    OutputOptions output;
    bool progress = true;             ///< the progress line on `err`
    std::function<bool()> shouldStop; ///< polled ~4 times a second; empty: stopSignalled()
};

struct RunReport
{
    bool complete = false;
    std::size_t total = 0;    ///< cells of this run
    std::size_t resumed = 0;  ///< read back from the partial file or a finished run's rows
    std::size_t computed = 0; ///< computed now
};

/// Throws ScanError / config::ConfigError before computing anything if the folder cannot be used.
RunReport runScan(const ScanSpec& spec, const std::filesystem::path& dir, const RunOptions& options,
                  std::ostream& out, std::ostream& err);

/// The cells a run still has to compute: those it owns that are not in `done`, ascending.
std::vector<std::size_t> pendingCells(const ScanSpec& spec, const RunFiles& files, const RowMap& done);

} // namespace rosin::scan
