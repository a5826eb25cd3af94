#include "lab/scan/Merge.h"

#include <map>
#include <regex>

#include "lab/scan/RunFiles.h"
#include "lab/scan/ScanError.h"
#include "lab/scan/SpecJson.h"

namespace rosin::scan
{

namespace fs = std::filesystem;

namespace
{
// Shard files found in the folder, by N then K.
std::map<std::size_t, std::map<std::size_t, fs::path>> findShards(const fs::path& dir)
{
    static const std::regex name(R"(scan\.shard-([0-9]+)-of-([0-9]+)\.csv)");
    std::map<std::size_t, std::map<std::size_t, fs::path>> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec))
    {
        std::smatch m;
        const std::string file = entry.path().filename().string();
        if (std::regex_match(file, m, name))
            found[std::stoul(m[2])][std::stoul(m[1])] = entry.path();
    }
    if (ec)
        throw ScanError(dir.string() + ": cannot be read (" + ec.message() + ")");
    return found;
}

std::string listText(const std::vector<std::size_t>& values, std::size_t limit = 20)
{
    std::string text;
    for (std::size_t i = 0; i < values.size() && i < limit; ++i)
        text += (i ? ", " : "") + std::to_string(values[i]);
    if (values.size() > limit)
        text += ", ... (" + std::to_string(values.size()) + " in all)";
    return text;
}

// The one N of the folder's shards, and a check that shards 0..N-1 are all there.
std::size_t checkShardSet(const fs::path& dir,
                          const std::map<std::size_t, std::map<std::size_t, fs::path>>& all)
{
    if (all.empty())
        throw ScanError(dir.string() + ": no shard files (scan.shard-K-of-N.csv) to merge");
    if (all.size() > 1)
    {
        std::vector<std::size_t> counts;
        for (const auto& [n, shards] : all)
            counts.push_back(n);
        throw ScanError(dir.string() + ": shard files of different splits (N = " + listText(counts) +
                        "); keep one split's files");
    }
    const auto& [n, shards] = *all.begin();
    std::vector<std::size_t> missing;
    for (std::size_t k = 0; k < n; ++k)
        if (shards.count(k) == 0)
            missing.push_back(k);
    if (!missing.empty())
    {
        std::string unfinished;
        for (const std::size_t k : missing)
            if (fs::exists(dir / (shardStem({k, n}) + ".partial.csv")))
                unfinished.append(" ").append(std::to_string(k)).append("/").append(std::to_string(n));
        throw ScanError(dir.string() + ": missing shard(s) " + listText(missing) + " of " +
                        std::to_string(n) + " (no scan.shard-K-of-" + std::to_string(n) + ".csv)" +
                        (unfinished.empty() ? "" : "; unfinished (partial file present):" + unfinished));
    }
    return n;
}

std::string commonSpec(const fs::path& dir, std::size_t n)
{
    std::string first;
    for (std::size_t k = 0; k < n; ++k)
    {
        const fs::path file = RunFiles(dir, ShardId{k, n}).spec();
        if (!fs::exists(file))
            throw ScanError(file.string() + " is missing: shard " + std::to_string(k) + "/" +
                            std::to_string(n) + " cannot be matched to the others");
        const std::string text = readTextFile(file);
        if (k == 0)
            first = text;
        else if (text != first)
            throw ScanError("shard " + std::to_string(k) + "/" + std::to_string(n) +
                            " was computed for a different scan specification than shard 0 (" +
                            describeSpecDifference(first, text) + ")");
    }
    return first;
}
} // namespace

void mergeShards(const fs::path& dir, const OutputOptions& options, std::ostream& out, std::ostream& err)
{
    if (!fs::is_directory(dir))
        throw ScanError(dir.string() + ": not a folder");
    const std::size_t n = checkShardSet(dir, findShards(dir));
    const std::string text = commonSpec(dir, n);
    const ScanSpec spec = specFromText(text, RunFiles(dir, ShardId{0, n}).spec().string());
    RowMap rows;
    std::vector<std::size_t> duplicated, missing;
    for (std::size_t k = 0; k < n; ++k)
    {
        const RunFiles files(dir, ShardId{k, n});
        for (auto& [cell, row] : readRowsFile(files.rows(), spec, false))
        {
            if (!files.owns(cell))
                throw ScanError(files.rows().string() + ": cell " + std::to_string(cell) +
                                " does not belong to shard " + std::to_string(k) + "/" + std::to_string(n));
            if (!rows.emplace(cell, std::move(row)).second)
                duplicated.push_back(cell);
        }
    }
    for (std::size_t cell = 0; cell < spec.cellCount(); ++cell)
        if (rows.count(cell) == 0)
            missing.push_back(cell);
    if (!missing.empty() || !duplicated.empty())
        throw ScanError(dir.string() + ": the shards do not cover every cell exactly once" +
                        (missing.empty() ? "" : "; missing cells: " + listText(missing)) +
                        (duplicated.empty() ? "" : "; repeated cells: " + listText(duplicated)));
    out << "merging " << n << " shard(s): " << rows.size() << " cells\n";
    writeScanOutputs(dir, text, rows, options, out, err);
}

} // namespace rosin::scan
