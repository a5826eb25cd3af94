#pragma once
// `rosin scan ... --mpi` under `mpirun -np R`: the cells are spread over the ranks (rank r computes the cells
// with index % R == r, on its own threads as usual); every finished row goes to rank 0 as text, which keeps
// the partial file and the progress line and, when every cell is in, writes exactly the files a single run
// writes (ScanOutput.h). Resuming works as for a single run: rank 0 reads the partial file and tells the
// others which cells are done. Built only with ROSIN_WITH_MPI (library rosin_scan_mpi).
#include <filesystem>
#include <ostream>

#include "lab/scan/ScanRun.h"

namespace rosin::scan
{

struct MpiRunReport
{
    bool root = false; ///< this process is rank 0 (which alone writes files and reports)
    int ranks = 1;
    RunReport report; ///< rank 0: the whole scan; other ranks: their own cells
};

/// Initialises and finalises MPI itself. `options.shard` must be empty. On rank 0 throws what a single run
/// would (ScanError ...) before any cell is computed; the other ranks then return with report.complete false.
MpiRunReport runScanMpi(const ScanSpec& spec, const std::filesystem::path& dir, const RunOptions& options,
                        std::ostream& out, std::ostream& err);

} // namespace rosin::scan
