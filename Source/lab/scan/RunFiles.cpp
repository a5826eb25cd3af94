#include "lab/scan/RunFiles.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <ostream>
#include <sstream>
#include <system_error>

#include "core/config/AtomicFile.h"
#include "core/config/ConfigError.h"
#include "lab/scan/CsvRow.h"
#include "lab/scan/ScanError.h"
#include "lab/scan/SpecJson.h"

namespace rosin::scan
{

namespace fs = std::filesystem;

std::string shardStem(const ShardId& shard)
{
    return "scan.shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count);
}

RunFiles::RunFiles(fs::path dir, std::optional<ShardId> shard)
    : dir_(std::move(dir)), shard_(shard), stem_(shard ? shardStem(*shard) : std::string("scan"))
{
}

bool RunFiles::owns(std::size_t cell) const noexcept
{
    return !shard_ || cell % shard_->count == shard_->index;
}

std::string readTextFile(const fs::path& file)
{
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw ScanError(file.string() + ": cannot be read");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeFileAtomically(const fs::path& file, const std::string& text)
{
    try
    {
        config::writeFileAtomically(file, text);
    }
    catch (const config::ConfigError& e)
    {
        throw ScanError(e.what());
    }
}

namespace
{
bool sameCoordinate(double stored, double nominal)
{
    return std::abs(stored - nominal) <= 1e-7 * std::max(1.0, std::abs(nominal));
}

// What is wrong with a parsed row of this scan, or empty: its cell must lie on the grid, at the grid's own
// coordinates (a row moved or edited by hand no longer matches them).
std::string rowProblem(const CellResult& row, const ScanSpec& spec)
{
    if (row.cell >= spec.cellCount())
        return "cell " + std::to_string(row.cell) + " is outside the grid of " +
               std::to_string(spec.cellCount()) + " cells";
    const CellSettings nominal = cellSettings(spec, row.cell);
    if (!sameCoordinate(row.beta, nominal.beta) || !sameCoordinate(row.bowForce, nominal.force) ||
        !sameCoordinate(row.second, nominal.second))
        return "cell " + std::to_string(row.cell) + " has other coordinates than the grid's (beta, force, " +
               std::string(spec.kind == ScanKind::Guettler ? "acceleration" : "bow speed") + ")";
    return {};
}

// Walks a rows file. Every bad line goes to `bad(line, what)`; strict readers throw from it, lenient ones
// note it and go on. Returns the good rows; a cell that appears twice with different contents is dropped.
RowMap walkRows(const fs::path& file, const ScanSpec& spec, bool tolerateTornLine,
                const std::function<void(std::size_t, const std::string&)>& bad)
{
    const std::string text = readTextFile(file);
    RowMap rows;
    std::map<std::size_t, std::size_t> firstLine;
    std::size_t begin = 0, lineNumber = 0;
    while (begin < text.size())
    {
        const std::size_t end = text.find('\n', begin);
        if (end == std::string::npos && tolerateTornLine)
            break; // a run killed while writing this row: it is computed again
        const std::string line =
            text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
        begin = end == std::string::npos ? text.size() : end + 1;
        if (++lineNumber == 1)
        {
            if (line != csvHeader(spec.kind))
            {
                bad(1, "expected the header \"" + csvHeader(spec.kind) + "\" of a " + kindName(spec.kind) +
                           " scan");
                return {}; // without its header no row can be trusted
            }
            continue;
        }
        if (end == std::string::npos)
        {
            bad(lineNumber, "cut off (no newline at the end of the file)");
            break;
        }
        CellResult row;
        try
        {
            row = parseRow(line);
        }
        catch (const std::invalid_argument& e)
        {
            bad(lineNumber, e.what());
            continue;
        }
        if (const std::string problem = rowProblem(row, spec); !problem.empty())
        {
            bad(lineNumber, problem);
            continue;
        }
        // A cell once contradicted stays out, whatever later lines of it say.
        if (const auto seen = firstLine.find(row.cell); seen != firstLine.end())
        {
            const auto kept = rows.find(row.cell);
            if (kept == rows.end() || kept->second != line)
            {
                bad(lineNumber, "cell " + std::to_string(row.cell) +
                                    " appears twice with different results (also line " +
                                    std::to_string(seen->second) + ")");
                if (kept != rows.end())
                    rows.erase(kept);
            }
            continue;
        }
        firstLine[row.cell] = lineNumber;
        rows.emplace(row.cell, line);
    }
    if (lineNumber == 0 && !tolerateTornLine)
        bad(0, "empty (expected the header \"" + csvHeader(spec.kind) + "\")");
    return rows;
}
} // namespace

RowMap readRowsFile(const fs::path& file, const ScanSpec& spec, bool tolerateTornLine)
{
    return walkRows(file, spec, tolerateTornLine,
                    [&](std::size_t line, const std::string& what) {
                        throw ScanError(file.string() + (line > 0 ? ": line " + std::to_string(line) : "") +
                                        ": " + what);
                    });
}

RowMap readGoodRows(const fs::path& file, const ScanSpec& spec, bool tolerateTornLine,
                    std::vector<std::string>& problems)
{
    return walkRows(file, spec, tolerateTornLine,
                    [&](std::size_t line, const std::string& what) {
                        problems.push_back(file.string() +
                                           (line > 0 ? ": line " + std::to_string(line) : "") + ": " + what);
                    });
}

void writeRowsFile(const fs::path& file, ScanKind kind, const RowMap& rows)
{
    std::string text = csvHeader(kind) + "\n";
    for (const auto& [cell, row] : rows)
        text += row + "\n";
    writeFileAtomically(file, text);
}

namespace
{
// The rows of an earlier run of the same specification, copied into the partial file, to which the cells
// still missing are appended. Bad rows are named on `warnings` and computed again.
RowMap resumeFrom(const fs::path& file, const RunFiles& files, const ScanSpec& spec, bool tolerateTornLine,
                  std::ostream& warnings)
{
    std::vector<std::string> problems;
    RowMap rows = readGoodRows(file, spec, tolerateTornLine, problems);
    for (auto it = rows.begin(); it != rows.end();)
        if (!files.owns(it->first))
        {
            problems.push_back(file.string() + ": cell " + std::to_string(it->first) +
                               " does not belong to this run's shard");
            it = rows.erase(it);
        }
        else
            ++it;
    for (const auto& problem : problems)
        warnings << "warning: " << problem << "; the cell is computed again\n";
    // Rewritten whole, so that new rows are not appended to a torn last line.
    writeRowsFile(files.partial(), spec.kind, rows);
    return rows;
}
} // namespace

RowMap startRun(const RunFiles& files, const ScanSpec& spec, const std::string& specText,
                std::ostream& warnings)
{
    std::error_code ec;
    fs::create_directories(files.dir(), ec);
    if (!fs::is_directory(files.dir()))
        throw ScanError(files.dir().string() + ": cannot create the output folder" +
                        (ec ? " (" + ec.message() + ")" : std::string()));
    if (!fs::exists(files.partial()))
    {
        if (fs::exists(files.rows()) && fs::exists(files.spec()) && readTextFile(files.spec()) == specText)
            return resumeFrom(files.rows(), files, spec, false, warnings); // finished: outputs written again
        writeFileAtomically(files.spec(), specText);
        return {};
    }
    if (!fs::exists(files.spec()))
        throw ScanError(files.partial().string() + " has no " + files.spec().filename().string() +
                        ", so it cannot be matched to this scan; remove it to start afresh");
    const std::string stored = readTextFile(files.spec());
    if (stored != specText)
        throw ScanError(files.partial().string() + " belongs to a different scan specification (" +
                        files.spec().string() +
                        "; this scan vs the stored one: " + describeSpecDifference(specText, stored) +
                        "). Use another --out folder, or remove the partial file to start afresh");
    return resumeFrom(files.partial(), files, spec, true, warnings);
}

} // namespace rosin::scan
