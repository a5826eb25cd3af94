#include "cli/ScanCompareCommand.h"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli/CommandLine.h"
#include "cli/OptionTable.h"
#include "lab/scan/Figures.h"
#include "lab/scan/ScanError.h"

namespace rosin::cli
{

namespace
{
namespace fs = std::filesystem;

/// A finished scan's summary; names the file and what is wrong with it.
nlohmann::json readSummary(const fs::path& dir)
{
    const fs::path csv = dir / "scan.csv", json = dir / "scan.json";
    for (const auto& f : {csv, json})
        if (!fs::is_regular_file(f))
            throw scan::ScanError(f.string() + ": expected a finished scan (scan.csv and scan.json) but the "
                                               "file is missing");
    std::ifstream in(json);
    try
    {
        return nlohmann::json::parse(in);
    }
    catch (const nlohmann::json::exception& e)
    {
        throw scan::ScanError(json.string() +
                              ": expected a scan summary (JSON) but it does not parse: " + e.what());
    }
}

double helmholtzShare(const nlohmann::json& summary, const fs::path& dir)
{
    const auto it = summary.find("helmholtzFraction");
    if (it == summary.end() || !it->is_number())
        throw scan::ScanError((dir / "scan.json").string() +
                              ": field \"helmholtzFraction\": expected a number but it is missing");
    return it->get<double>();
}
} // namespace

const OptionTable& scanCompareOptionTable()
{
    static const OptionTable table(
        {{"--out", "DIR", "the folder of the difference figure (DIR/compare.png)"}});
    return table;
}

ScanComparison parseScanCompare(const std::vector<std::string>& args)
{
    ScanComparison c;
    std::vector<std::string> options;
    for (const auto& a : args)
        (a.rfind("--", 0) == 0 || !options.empty() ? options : c.folders).push_back(a);
    const ParsedOptions parsed = scanCompareOptionTable().parse(options);
    c.out = parsed.value("--out") ? *parsed.value("--out") : "";
    if (c.folders.size() != 2 || c.out.empty())
        throw UsageError("usage: rosin scan compare A B --out DIR (A and B: folders of two finished scans)");
    return c;
}

int runScanCompare(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
{
    const ScanComparison c = parseScanCompare(args);
    const std::vector<std::string>& folders = c.folders;
    const std::string& outDir = c.out;
    const nlohmann::json a = readSummary(folders[0]), b = readSummary(folders[1]);
    if (a.value("kind", "") != b.value("kind", ""))
        throw scan::ScanError("cannot compare " + folders[0] + " (" + a.value("kind", "?") + ") with " +
                              folders[1] + " (" + b.value("kind", "?") + "): expected two scans of one kind");
    fs::create_directories(outDir);
    const double shareA = helmholtzShare(a, folders[0]), shareB = helmholtzShare(b, folders[1]);
    out << "Helmholtz cells: " << 100.0 * shareA << " % (" << folders[0] << ") -> " << 100.0 * shareB
        << " % (" << folders[1] << ")\n";
    out.flush(); // before the script writes to the same terminal
    if (!scan::runFigureScript({"compare", folders[0], folders[1], "--out", outDir}, err, "\n"))
        return kExitInputError;
    return kExitOk;
}

} // namespace rosin::cli
