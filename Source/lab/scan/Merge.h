#pragma once
// `rosin scan merge DIR`: the shards of a scan (DIR/scan.shard-K-of-N.csv with their .spec.json, written by
// `--shard K/N` runs) into the files a single run writes (ScanOutput.h), byte for byte. Every shard must be
// present and finished, all with the same N and the same specification, and together cover every cell exactly
// once; otherwise a ScanError names the missing shards or cells (or the differing specification).
#include <filesystem>
#include <ostream>

#include "lab/scan/ScanOutput.h"

namespace rosin::scan
{

void mergeShards(const std::filesystem::path& dir, const OutputOptions& options, std::ostream& out,
                 std::ostream& err);

} // namespace rosin::scan
