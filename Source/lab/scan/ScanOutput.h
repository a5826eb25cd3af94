#pragma once
// The final files of a complete scan, the same whichever way its cells were computed (one process, threads,
// resumed, shards merged, MPI ranks): DIR/scan.csv (rows sorted by cell), DIR/scan.spec.json and
// DIR/scan.json, the summary computed from the rows as written (parsed back) and the specification as
// stored, then the figures. Only the rows' text and the specification's text go in, so equal inputs give
// byte-identical files.
#include <filesystem>
#include <ostream>
#include <string>

#include "lab/scan/RunFiles.h"

namespace rosin::scan
{

struct OutputOptions
{
    bool figures = true;
};

/// `rows` must hold every cell of the specification. Throws ScanError (a missing cell, a bad row) or
/// config::ConfigError (a bad specification text). Reports the files written to `out`.
void writeScanOutputs(const std::filesystem::path& dir, const std::string& specText, const RowMap& rows,
                      const OutputOptions& options, std::ostream& out, std::ostream& err);

} // namespace rosin::scan
