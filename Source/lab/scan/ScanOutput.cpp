#include "lab/scan/ScanOutput.h"

#include <cstdio>

#include "lab/scan/CsvRow.h"
#include "lab/scan/Figures.h"
#include "lab/scan/ScanError.h"
#include "lab/scan/SpecJson.h"
#include "lab/scan/Summary.h"

namespace rosin::scan
{

namespace fs = std::filesystem;

namespace
{
std::vector<CellResult> parseAll(const ScanSpec& spec, const RowMap& rows)
{
    if (rows.size() != spec.cellCount())
        throw ScanError("internal: " + std::to_string(rows.size()) + " rows for " +
                        std::to_string(spec.cellCount()) + " cells");
    std::vector<CellResult> results;
    results.reserve(rows.size());
    std::size_t expected = 0;
    for (const auto& [cell, row] : rows)
    {
        if (cell != expected++)
            throw ScanError("internal: cell " + std::to_string(expected - 1) + " is missing");
        results.push_back(parseRow(row));
    }
    return results;
}

std::string summaryLine(const nlohmann::json& summary)
{
    char text[200];
    std::snprintf(text, sizeof text, "%zu cells, %zu Helmholtz (%.1f %%)",
                  summary["cells"].get<std::size_t>(), summary["helmholtzCells"].get<std::size_t>(),
                  100.0 * summary["helmholtzFraction"].get<double>());
    std::string line = text;
    if (summary.contains("reachedFraction"))
    {
        std::snprintf(text, sizeof text, ", Helmholtz within %g periods: %.1f %%",
                      summary["transientCapPeriods"].get<double>(),
                      100.0 * summary["reachedFraction"].get<double>());
        line += text;
    }
    return line;
}
} // namespace

void writeScanOutputs(const fs::path& dir, const std::string& specText, const RowMap& rows,
                      const OutputOptions& options, std::ostream& out, std::ostream& err)
{
    const ScanSpec spec = specFromText(specText, (dir / "scan.spec.json").string());
    const nlohmann::json summary = scanSummary(spec, parseAll(spec, rows));
    writeRowsFile(dir / "scan.csv", spec.kind, rows);
    writeFileAtomically(dir / "scan.spec.json", specText);
    writeFileAtomically(dir / "scan.json", summary.dump(2) + "\n");
    out << "wrote " << (dir / "scan.csv").string() << " and " << (dir / "scan.json").string() << ": "
        << summaryLine(summary) << "\n"
        << std::flush;
    if (options.figures && drawFigures(dir, err))
        out << "figures written to " << dir.string() << "\n";
}

} // namespace rosin::scan
