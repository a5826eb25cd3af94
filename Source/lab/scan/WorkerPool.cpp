#include "lab/scan/WorkerPool.h"

#include <algorithm>
#include <optional>

#include "lab/scan/CellRunner.h"
#include "lab/scan/CsvRow.h"

namespace rosin::scan
{

unsigned defaultThreadCount() noexcept
{
    return std::max(1u, std::thread::hardware_concurrency());
}

WorkerPool::WorkerPool(const ScanSpec& spec, std::vector<std::size_t> cells, unsigned threads)
    : pool_(std::move(cells), threads,
            [&spec](const JobPool<std::string>::Next& next, const JobPool<std::string>::Deliver& deliver)
            {
                CellRunner runner(spec); // prepares this thread's voice (a thermal law calibrates: ~25 ms)
                runner.runAll(next, [&deliver](const CellResult& result)
                              { deliver(result.cell, formatRow(result)); });
            })
{
}

std::vector<FinishedCell> WorkerPool::take(std::chrono::milliseconds wait)
{
    std::vector<FinishedCell> rows;
    for (auto& [cell, row] : pool_.take(wait))
        rows.push_back({cell, std::move(row)});
    return rows;
}

void drainPool(WorkerPool& pool, const std::function<void(const FinishedCell&)>& sink,
               const std::function<bool()>& shouldStop, const std::function<void()>& idle,
               std::chrono::milliseconds wait)
{
    while (!pool.finished())
    {
        for (const FinishedCell& row : pool.take(wait))
            sink(row);
        if (shouldStop && shouldStop())
            pool.stop();
        if (idle)
            idle();
    }
}

} // namespace rosin::scan
