#include "lab/scan/mpi/MpiScan.h"

#include <mpi.h>

#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "lab/scan/CsvRow.h"
#include "lab/scan/Figures.h"
#include "lab/scan/PartialWriter.h"
#include "lab/scan/Progress.h"
#include "lab/scan/SpecJson.h"
#include "lab/scan/StopSignal.h"
#include "lab/scan/WorkerPool.h"

namespace rosin::scan
{

namespace fs = std::filesystem;

namespace
{
constexpr int kRowTag = 1;  ///< a finished row's text
constexpr int kDoneTag = 2; ///< a rank has no more rows (finished or stopped)

// MPI_Init_thread / MPI_Finalize for the lifetime of one run: only the main thread calls MPI.
struct MpiSession
{
    int rank = 0, size = 1;
    MpiSession()
    {
        int provided = 0;
        MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Comm_size(MPI_COMM_WORLD, &size);
    }
    ~MpiSession() { MPI_Finalize(); }
};

// Rank 0 prepares the folder (startRun) and broadcasts either the done cells or that it failed (then every
// rank gets nothing, and rank 0 holds the failure).
std::optional<RowMap> shareStart(const MpiSession& mpi, const RunFiles& files, const ScanSpec& spec,
                                 const std::string& text, std::ostream& err, std::exception_ptr& failure)
{
    RowMap rows;
    int ok = 1;
    if (mpi.rank == 0)
    {
        try
        {
            rows = startRun(files, spec, text, err);
        }
        catch (...)
        {
            failure = std::current_exception();
            ok = 0;
        }
    }
    MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (!ok)
        return std::nullopt;
    std::vector<unsigned long long> done;
    for (const auto& [cell, row] : rows)
        done.push_back(cell);
    unsigned long long count = done.size();
    MPI_Bcast(&count, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    done.resize(count);
    MPI_Bcast(done.data(), static_cast<int>(count), MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    if (mpi.rank != 0)
        for (const auto cell : done)
            rows.emplace(static_cast<std::size_t>(cell), std::string());
    return rows;
}

std::vector<std::size_t> rankCells(const ScanSpec& spec, const RowMap& done, const MpiSession& mpi)
{
    std::vector<std::size_t> cells;
    for (std::size_t cell = static_cast<std::size_t>(mpi.rank); cell < spec.cellCount();
         cell += static_cast<std::size_t>(mpi.size))
        if (done.count(cell) == 0)
            cells.push_back(cell);
    return cells;
}

// One pending message to rank 0, received whole; returns the tag.
int receive(std::string& text, bool wait)
{
    int flag = 0;
    MPI_Status status;
    if (wait)
    {
        MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
        flag = 1;
    }
    else
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (!flag)
        return 0;
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    text.assign(static_cast<std::size_t>(length), '\0');
    MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    return status.MPI_TAG;
}

void sendRow(const std::string& row)
{
    MPI_Send(row.data(), static_cast<int>(row.size()), MPI_CHAR, 0, kRowTag, MPI_COMM_WORLD);
}

void workerRank(const ScanSpec& spec, const std::vector<std::size_t>& cells, const RunOptions& o,
                RunReport& report)
{
    {
        WorkerPool pool(spec, cells, o.threads > 0 ? o.threads : defaultThreadCount());
        drainPool(
            pool,
            [&](const FinishedCell& c)
            {
                sendRow(c.row);
                ++report.computed;
            },
            o.shouldStop ? o.shouldStop : std::function<bool()>(stopSignalled), nullptr,
            std::chrono::milliseconds(250));
    }
    MPI_Send(nullptr, 0, MPI_CHAR, 0, kDoneTag, MPI_COMM_WORLD);
}

// Rank 0: its own cells, the other ranks' rows as they arrive, until every rank is done.
void rootRank(const ScanSpec& spec, const RunFiles& files, const std::vector<std::size_t>& cells,
              const MpiSession& mpi, const RunOptions& o, RowMap& rows, Progress& progress, RunReport& report)
{
    PartialWriter partial(files.partial(), spec.kind);
    int doneRanks = 0;
    auto keep = [&](std::size_t cell, const std::string& row)
    {
        partial.append(row);
        rows.emplace(cell, row);
        ++report.computed;
        progress.add(1);
    };
    auto poll = [&](bool wait)
    {
        std::string text;
        for (int tag = receive(text, wait); tag != 0; tag = receive(text, false))
        {
            if (tag == kDoneTag)
                ++doneRanks;
            else
                keep(rowCell(text), text);
            wait = false;
        }
    };
    {
        WorkerPool pool(spec, cells, o.threads > 0 ? o.threads : defaultThreadCount());
        drainPool(
            pool, [&](const FinishedCell& c) { keep(c.cell, c.row); },
            o.shouldStop ? o.shouldStop : std::function<bool()>(stopSignalled),
            [&]
            {
                poll(false);
                progress.tick();
            },
            std::chrono::milliseconds(50));
    }
    while (doneRanks < mpi.size - 1)
        poll(true);
}

// Rank 0 after every rank is done: the final files (figures come after MPI_Finalize: no fork() inside an MPI
// job), or the note that the run was stopped.
bool finishRoot(const ScanSpec& spec, const fs::path& dir, const std::string& text, const RunFiles& files,
                const RowMap& rows, const RunOptions& o, std::ostream& out, std::ostream& err)
{
    if (rows.size() < spec.cellCount())
    {
        out << "stopped: " << rows.size() << " of " << spec.cellCount() << " cells kept in "
            << files.partial().string() << "; run the same command again to resume\n";
        return false;
    }
    OutputOptions noFigures = o.output;
    noFigures.figures = false;
    writeScanOutputs(dir, text, rows, noFigures, out, err);
    std::error_code ec;
    fs::remove(files.partial(), ec);
    return true;
}

void runRanks(const MpiSession& mpi, const ScanSpec& spec, const fs::path& dir, const RunOptions& o,
              std::ostream& out, std::ostream& err, MpiRunReport& result, std::exception_ptr& failure)
{
    const std::string text = specText(spec);
    const RunFiles files(dir, std::nullopt);
    std::optional<RowMap> started = shareStart(mpi, files, spec, text, err, failure);
    if (!started)
        return;
    RowMap& rows = *started;
    const auto cells = rankCells(spec, rows, mpi);
    RunReport& report = result.report;
    if (!result.root)
    {
        report.total = cells.size();
        workerRank(spec, cells, o, report);
        return;
    }
    report.total = spec.cellCount();
    report.resumed = rows.size();
    if (report.resumed > 0)
        out << "resuming: " << report.resumed << " of " << report.total << " cells read back from "
            << files.partial().string() << "\n";
    Progress progress(err, report.total, rows.size(), o.progress);
    rootRank(spec, files, cells, mpi, o, rows, progress, report);
    progress.finish(rows.size() == report.total);
    report.complete = finishRoot(spec, dir, text, files, rows, o, out, err);
}
} // namespace

MpiRunReport runScanMpi(const ScanSpec& spec, const fs::path& dir, const RunOptions& o, std::ostream& out,
                        std::ostream& err)
{
    MpiRunReport result;
    std::exception_ptr failure;
    {
        const MpiSession mpi;
        result.root = mpi.rank == 0;
        result.ranks = mpi.size;
        try
        {
            runRanks(mpi, spec, dir, o, out, err, result, failure);
        }
        catch (const std::exception& e)
        {
            // Mid-run failure (a write error, a worker's exception): the other ranks cannot finish the
            // protocol, so the whole job ends; every row already written to the partial file is kept.
            err << "error: rank " << mpi.rank << ": " << e.what() << "\n" << std::flush;
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
    }
    if (failure && result.root)
        std::rethrow_exception(failure);
    if (result.root && result.report.complete && o.output.figures && drawFigures(dir, err))
        out << "figures written to " << dir.string() << "\n";
    return result;
}

} // namespace rosin::scan
