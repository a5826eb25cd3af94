#pragma once
// Where a trial's file is. The spec wants it "relative to the dataset folder, inside it": an absolute path, a
// path that climbs out with "..", or one that leaves through a symbolic link would let a dataset read (or a
// generator overwrite) files elsewhere.
#include <filesystem>
#include <optional>
#include <string>

namespace rosin::discovery
{

struct Dataset;
struct Trial;

/// Why `file` is not a path inside `folder`, or std::nullopt when it is. Symbolic links are followed as far
/// as they exist (std::filesystem::weakly_canonical), so the file itself need not exist yet.
std::optional<std::string> trialFileProblem(const std::filesystem::path& folder, const std::string& file);
/// folder / file, after checking it stays inside the folder; throws DatasetError naming dataset.json and
/// "trials[i].file" otherwise.
std::filesystem::path trialFilePath(const Dataset& dataset, const Trial& trial);

} // namespace rosin::discovery
