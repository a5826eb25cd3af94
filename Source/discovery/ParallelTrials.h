#pragma once
// Trials computed on several threads, each thread with its own worker (for a simulation: one prepared voice,
// as rosin scan's WorkerPool keeps one CellRunner per thread; that pool is tied to scan cells and CSV rows,
// so this is the same pattern for any per-trial result). Threads take the next job from a shared counter;
// results reach the calling thread, which alone writes files, in whatever order they finish. Each job is
// computed independently and deterministically, so what is written does not depend on the split.
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace rosin::discovery
{

/// Runs compute(job) for every job of `jobs` (in that order of starting) on min(threads, jobs) threads;
/// each thread makes its own compute function with makeWorker() first. take(job, result) runs on the calling
/// thread for every result. An exception in a worker or in `take` stops the remaining jobs; it is rethrown
/// here once every thread has finished.
template <class Result>
void runParallel(const std::vector<std::size_t>& jobs, unsigned threads,
                 const std::function<std::function<Result(std::size_t)>()>& makeWorker,
                 const std::function<void(std::size_t, Result&&)>& take)
{
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stopping{false};
    std::mutex mutex;
    std::condition_variable ready;
    std::vector<std::pair<std::size_t, Result>> done;
    std::exception_ptr error;
    const std::size_t count = jobs.empty() ? 0 : std::clamp<std::size_t>(threads, 1, jobs.size());
    std::size_t running = count;

    auto work = [&]
    {
        try
        {
            auto compute = makeWorker();
            for (std::size_t i = next++; i < jobs.size() && !stopping; i = next++)
            {
                Result result = compute(jobs[i]);
                const std::lock_guard lock(mutex);
                done.emplace_back(jobs[i], std::move(result));
                ready.notify_all();
            }
        }
        catch (...)
        {
            stopping = true;
            const std::lock_guard lock(mutex);
            if (!error)
                error = std::current_exception();
        }
        const std::lock_guard lock(mutex);
        --running;
        ready.notify_all();
    };
    std::vector<std::thread> pool;
    for (std::size_t i = 0; i < count; ++i)
        pool.emplace_back(work);

    try
    {
        for (;;)
        {
            std::vector<std::pair<std::size_t, Result>> batch;
            {
                std::unique_lock lock(mutex);
                ready.wait(lock, [&] { return !done.empty() || running == 0; });
                if (error)
                    break;
                batch.swap(done);
                if (batch.empty() && running == 0)
                    break;
            }
            for (auto& [job, result] : batch)
                take(job, std::move(result));
        }
    }
    catch (...)
    {
        stopping = true;
        const std::lock_guard lock(mutex);
        if (!error)
            error = std::current_exception();
    }
    for (auto& t : pool)
        t.join();
    if (error)
        std::rethrow_exception(error);
}

} // namespace rosin::discovery
