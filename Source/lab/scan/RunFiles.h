#pragma once
// The files of one run in the output folder. A run computes every cell (stem "scan") or the cells of one
// shard (index % N == K, stem "scan.shard-K-of-N"):
//   STEM.spec.json     the specification (SpecJson.h), written before the first cell
//   STEM.partial.csv   the header and each finished cell's row, appended and flushed as it finishes, in the
//                      order the cells finished: an interrupted run resumes from it
//   STEM.csv           the rows sorted by cell, written when every cell of the run is done (the partial
//                      file is then removed)
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

/// Shard K of N (Slurm job arrays): the cells with index % N == K.
struct ShardId
{
    std::size_t index = 0;
    std::size_t count = 1;
};

/// Finished rows by cell (each row without its newline).
using RowMap = std::map<std::size_t, std::string>;

class RunFiles
{
  public:
    RunFiles(std::filesystem::path dir, std::optional<ShardId> shard);

    const std::filesystem::path& dir() const noexcept { return dir_; }
    const std::optional<ShardId>& shard() const noexcept { return shard_; }
    std::filesystem::path rows() const { return dir_ / (stem_ + ".csv"); }
    std::filesystem::path partial() const { return dir_ / (stem_ + ".partial.csv"); }
    std::filesystem::path spec() const { return dir_ / (stem_ + ".spec.json"); }
    /// Whether this run computes the cell.
    bool owns(std::size_t cell) const noexcept;

  private:
    std::filesystem::path dir_;
    std::optional<ShardId> shard_;
    std::string stem_;
};

/// "scan.shard-K-of-N".
std::string shardStem(const ShardId& shard);

/// Prepares a run before its first cell: creates the folder, and either checks an existing partial file
/// against the specification and returns its rows (resume), or returns the rows of a finished run of the
/// same specification (STEM.csv: nothing to compute, the outputs are written again), or writes the
/// specification and starts afresh (a finished run of another specification is replaced when this one
/// completes). Rows read back that are malformed, off the grid, cut off or contradicted (a damaged or
/// hand-edited file) are named on `warnings` and left out, so their cells are computed again. Throws
/// ScanError if the partial file belongs to another specification or a file cannot be read.
RowMap startRun(const RunFiles& files, const ScanSpec& spec, const std::string& specText,
                std::ostream& warnings);

/// Reads a rows file (partial or complete) of this kind: the header, then one row per line, each on the
/// spec's grid at its own coordinates. A last line without its newline (a run killed mid-write) is dropped
/// when `tolerateTornLine`. Throws ScanError naming the file and line if a row is malformed, off the grid, or
/// repeated with different contents.
RowMap readRowsFile(const std::filesystem::path& file, const ScanSpec& spec, bool tolerateTornLine);
/// The same, but a bad line is described in `problems` ("FILE: line N: what") and left out instead; a cell
/// repeated with different contents is left out altogether.
RowMap readGoodRows(const std::filesystem::path& file, const ScanSpec& spec, bool tolerateTornLine,
                    std::vector<std::string>& problems);

/// Writes the header and the rows in cell order (to a temporary file, then renamed into place).
void writeRowsFile(const std::filesystem::path& file, ScanKind kind, const RowMap& rows);
/// Writes text to a file through a temporary file and a rename. Throws ScanError on failure.
void writeFileAtomically(const std::filesystem::path& file, const std::string& text);
/// The whole file as text (ScanError if it cannot be read).
std::string readTextFile(const std::filesystem::path& file);

} // namespace rosin::scan
