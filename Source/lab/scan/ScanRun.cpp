#include "lab/scan/ScanRun.h"

#include "lab/scan/PartialWriter.h"
#include "lab/scan/Progress.h"
#include "lab/scan/SpecJson.h"
#include "lab/scan/StopSignal.h"
#include "lab/scan/WorkerPool.h"

namespace rosin::scan
{

namespace fs = std::filesystem;

std::vector<std::size_t> pendingCells(const ScanSpec& spec, const RunFiles& files, const RowMap& done)
{
    std::vector<std::size_t> cells;
    for (std::size_t cell = 0; cell < spec.cellCount(); ++cell)
        if (files.owns(cell) && done.count(cell) == 0)
            cells.push_back(cell);
    return cells;
}

namespace
{
std::size_t ownedCells(const ScanSpec& spec, const RunFiles& files)
{
    std::size_t n = 0;
    for (std::size_t cell = 0; cell < spec.cellCount(); ++cell)
        n += files.owns(cell) ? 1 : 0;
    return n;
}

void finishRun(const RunFiles& files, const ScanSpec& spec, const std::string& text, const RowMap& rows,
               const RunOptions& o, std::ostream& out, std::ostream& err)
{
    if (files.shard())
    {
        writeRowsFile(files.rows(), spec.kind, rows);
        out << "wrote " << files.rows().string() << ": " << rows.size() << " cells of shard "
            << files.shard()->index << "/" << files.shard()->count
            << "; when every shard is done: rosin scan merge " << files.dir().string() << "\n";
    }
    else
        writeScanOutputs(files.dir(), text, rows, o.output, out, err);
    std::error_code ec;
    fs::remove(files.partial(), ec);
}
} // namespace

RunReport runScan(const ScanSpec& spec, const fs::path& dir, const RunOptions& o, std::ostream& out,
                  std::ostream& err)
{
    const std::string text = specText(spec);
    const RunFiles files(dir, o.shard);
    const bool interrupted = fs::exists(files.partial());
    RowMap rows = startRun(files, spec, text, err);
    RunReport report;
    report.total = ownedCells(spec, files);
    report.resumed = rows.size();
    const std::vector<std::size_t> pending = pendingCells(spec, files, rows);
    if (report.resumed > 0)
        out << (interrupted ? "resuming: " : "already computed: ") << report.resumed << " of " << report.total
            << " cells read back from " << (interrupted ? files.partial() : files.rows()).string() << "\n";
    Progress progress(err, report.total, rows.size(), o.progress);
    if (!pending.empty())
    {
        PartialWriter partial(files.partial(), spec.kind);
        WorkerPool pool(spec, pending, o.threads > 0 ? o.threads : defaultThreadCount());
        const auto stop = o.shouldStop ? o.shouldStop : std::function<bool()>(stopSignalled);
        drainPool(
            pool,
            [&](const FinishedCell& c)
            {
                partial.append(c.row);
                rows.emplace(c.cell, c.row);
                ++report.computed;
                progress.add(1);
            },
            stop, [&] { progress.tick(); }, std::chrono::milliseconds(250));
    }
    report.complete = rows.size() == report.total;
    progress.finish(report.complete);
    if (report.complete)
        finishRun(files, spec, text, rows, o, out, err);
    else
        out << "stopped: " << rows.size() << " of " << report.total << " cells kept in "
            << files.partial().string() << "; run the same command again to resume\n";
    return report;
}

} // namespace rosin::scan
