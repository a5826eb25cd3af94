#include "RunFiles.h"

#include <fstream>
#include <sstream>
#include <system_error>

#include "CsvRow.h"
#include "ScanError.h"
#include "SpecJson.h"

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
    const fs::path temporary = file.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << text;
        out.flush();
        if (!out)
            throw ScanError(temporary.string() + ": cannot be written");
    }
    std::error_code ec;
    fs::rename(temporary, file, ec);
    if (ec)
        throw ScanError(file.string() + ": cannot be written (" + ec.message() + ")");
}

RowMap readRowsFile(const fs::path& file, const ScanSpec& spec, bool tolerateTornLine)
{
    const std::string text = readTextFile(file);
    RowMap rows;
    std::size_t begin = 0, lineNumber = 0;
    while (begin < text.size())
    {
        const std::size_t end = text.find('\n', begin);
        if (end == std::string::npos && tolerateTornLine)
            break; // a run killed while writing this row: it is computed again
        const std::string line =
            text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
        begin = end == std::string::npos ? text.size() : end + 1;
        auto fail = [&](const std::string& what)
        { throw ScanError(file.string() + ": line " + std::to_string(lineNumber) + ": " + what); };
        if (++lineNumber == 1)
        {
            if (line != csvHeader(spec.kind))
                fail("expected the header \"" + csvHeader(spec.kind) + "\" of a " + kindName(spec.kind) +
                     " scan");
            continue;
        }
        CellResult row;
        try
        {
            row = parseRow(line);
        }
        catch (const std::invalid_argument& e)
        {
            fail(e.what());
        }
        if (row.cell >= spec.cellCount())
            fail("cell " + std::to_string(row.cell) + " is outside the grid of " +
                 std::to_string(spec.cellCount()) + " cells");
        const auto [at, inserted] = rows.emplace(row.cell, line);
        if (!inserted && at->second != line)
            fail("cell " + std::to_string(row.cell) + " appears twice with different results");
    }
    if (lineNumber == 0 && tolerateTornLine)
        return rows; // killed while writing the header
    if (lineNumber == 0)
        throw ScanError(file.string() + ": empty (expected the header \"" + csvHeader(spec.kind) + "\")");
    return rows;
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
// still missing are appended.
RowMap resumeFrom(const fs::path& file, const RunFiles& files, const ScanSpec& spec, bool tolerateTornLine)
{
    RowMap rows = readRowsFile(file, spec, tolerateTornLine);
    for (const auto& [cell, row] : rows)
        if (!files.owns(cell))
            throw ScanError(file.string() + ": cell " + std::to_string(cell) +
                            " does not belong to this run's shard");
    // Rewritten whole, so that new rows are not appended to a torn last line.
    writeRowsFile(files.partial(), spec.kind, rows);
    return rows;
}
} // namespace

RowMap startRun(const RunFiles& files, const ScanSpec& spec, const std::string& specText)
{
    std::error_code ec;
    fs::create_directories(files.dir(), ec);
    if (!fs::is_directory(files.dir()))
        throw ScanError(files.dir().string() + ": cannot create the output folder" +
                        (ec ? " (" + ec.message() + ")" : std::string()));
    if (!fs::exists(files.partial()))
    {
        if (fs::exists(files.rows()) && fs::exists(files.spec()) && readTextFile(files.spec()) == specText)
            return resumeFrom(files.rows(), files, spec, false); // a finished run: outputs written again
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
    return resumeFrom(files.partial(), files, spec, true);
}

} // namespace rosin::scan
