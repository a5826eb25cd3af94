#pragma once
// Appends finished rows to a run's partial file, one line each, flushed at once: a run stopped at any point
// (Ctrl-C, a Slurm time limit, a crash) keeps every row it reported.
#include <cstdio>
#include <filesystem>
#include <string>

#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

class PartialWriter
{
  public:
    /// Opens for appending; a new (or empty) file gets the header first. Throws ScanError.
    PartialWriter(const std::filesystem::path& file, ScanKind kind);
    ~PartialWriter();
    PartialWriter(const PartialWriter&) = delete;
    PartialWriter& operator=(const PartialWriter&) = delete;

    /// The row and a newline, flushed. Throws ScanError if the write fails.
    void append(const std::string& row);
    /// Closes the file (also done by the destructor).
    void close();

  private:
    std::filesystem::path path_;
    std::FILE* file_ = nullptr;
};

} // namespace rosin::scan
