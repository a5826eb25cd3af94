#include "WorkerPool.h"

#include <algorithm>
#include <optional>

#include "CellRunner.h"
#include "CsvRow.h"

namespace rosin::scan
{

unsigned defaultThreadCount() noexcept
{
    return std::max(1u, std::thread::hardware_concurrency());
}

WorkerPool::WorkerPool(const ScanSpec& spec, std::vector<std::size_t> cells, unsigned threads)
    : cells_(std::move(cells))
{
    const std::size_t n = cells_.empty() ? 0 : std::clamp<std::size_t>(threads, 1, cells_.size());
    running_ = n;
    for (std::size_t i = 0; i < n; ++i)
        threads_.emplace_back([this, &spec] { work(spec); });
}

WorkerPool::~WorkerPool()
{
    stop();
    for (auto& t : threads_)
        t.join();
}

void WorkerPool::work(const ScanSpec& spec)
{
    try
    {
        CellRunner runner(spec); // prepares this thread's voice (a thermal law calibrates: ~25 ms)
        runner.runAll(
            [this]() -> std::optional<std::size_t>
            {
                const std::size_t i = stopping_ ? cells_.size() : next_++;
                return i < cells_.size() ? std::optional(cells_[i]) : std::nullopt;
            },
            [this](const CellResult& result)
            {
                FinishedCell row{result.cell, formatRow(result)};
                const std::lock_guard lock(mutex_);
                done_.push_back(std::move(row));
                ready_.notify_all();
            });
    }
    catch (...)
    {
        stopping_ = true;
        const std::lock_guard lock(mutex_);
        if (!error_)
            error_ = std::current_exception();
    }
    const std::lock_guard lock(mutex_);
    --running_;
    ready_.notify_all();
}

std::vector<FinishedCell> WorkerPool::take(std::chrono::milliseconds wait)
{
    std::unique_lock lock(mutex_);
    ready_.wait_for(lock, wait, [this] { return !done_.empty() || running_ == 0 || error_; });
    if (error_)
        std::rethrow_exception(error_);
    std::vector<FinishedCell> rows;
    rows.swap(done_);
    return rows;
}

bool WorkerPool::finished()
{
    const std::lock_guard lock(mutex_);
    if (error_)
        std::rethrow_exception(error_);
    return running_ == 0 && done_.empty();
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
