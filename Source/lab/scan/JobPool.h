#pragma once
// The one thread pool of the lab: numbered jobs computed on several threads, each thread with its own worker
// (for a simulation: one prepared voice, or a runner with SIMD lanes that takes the next job whenever a lane
// is free). Threads take jobs from a shared counter, so the split varies from run to run; every job is
// computed independently and deterministically, so results do not depend on it. Results reach the owning
// thread through take(), which alone writes files, counts and (MPI) sends. Used by rosin scan's cells
// (WorkerPool.h) and rosin discover's trials (discovery/ParallelTrials.h).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace rosin::scan
{

template <class Result> class JobPool
{
  public:
    /// The next job for this thread's worker, or none when the pool has no more (or is stopping).
    using Next = std::function<std::optional<std::size_t>()>;
    /// A finished job's result, from any worker thread.
    using Deliver = std::function<void(std::size_t job, Result&& result)>;
    /// What each thread runs: it makes its worker, then computes jobs from `next` until there are none, each
    /// result to `deliver` (in any order). An exception stops the pool; take() rethrows it.
    using Work = std::function<void(const Next& next, const Deliver& deliver)>;

    /// Starts min(threads, jobs) threads (at least one if there are jobs); jobs start in the order given.
    JobPool(std::vector<std::size_t> jobs, unsigned threads, Work work)
        : jobs_(std::move(jobs)), work_(std::move(work))
    {
        const std::size_t n = jobs_.empty() ? 0 : std::clamp<std::size_t>(threads, 1, jobs_.size());
        running_ = n;
        for (std::size_t i = 0; i < n; ++i)
            threads_.emplace_back([this] { run(); });
    }
    /// Stops taking new jobs and waits for the running ones.
    ~JobPool()
    {
        stop();
        for (auto& t : threads_)
            t.join();
    }
    JobPool(const JobPool&) = delete;
    JobPool& operator=(const JobPool&) = delete;

    /// Results finished since the last call, waiting up to `wait` for the first. Rethrows a worker's
    /// exception.
    std::vector<std::pair<std::size_t, Result>> take(std::chrono::milliseconds wait)
    {
        std::unique_lock lock(mutex_);
        ready_.wait_for(lock, wait, [this] { return !done_.empty() || running_ == 0 || error_; });
        if (error_)
            std::rethrow_exception(error_);
        std::vector<std::pair<std::size_t, Result>> results;
        results.swap(done_);
        return results;
    }
    /// No new jobs are started; running ones finish and are still reported.
    void stop() noexcept { stopping_ = true; }
    /// Every thread has exited and every result has been taken. Rethrows a worker's exception.
    bool finished()
    {
        const std::lock_guard lock(mutex_);
        if (error_)
            std::rethrow_exception(error_);
        return running_ == 0 && done_.empty();
    }

  private:
    void run()
    {
        try
        {
            work_(
                [this]() -> std::optional<std::size_t>
                {
                    const std::size_t i = stopping_ ? jobs_.size() : next_++;
                    return i < jobs_.size() ? std::optional(jobs_[i]) : std::nullopt;
                },
                [this](std::size_t job, Result&& result)
                {
                    const std::lock_guard lock(mutex_);
                    done_.emplace_back(job, std::move(result));
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

    std::vector<std::size_t> jobs_;
    Work work_;
    std::atomic<std::size_t> next_{0};
    std::atomic<bool> stopping_{false};
    std::mutex mutex_;
    std::condition_variable ready_;
    std::vector<std::pair<std::size_t, Result>> done_;
    std::exception_ptr error_;
    std::size_t running_ = 0;
    std::vector<std::thread> threads_;
};

} // namespace rosin::scan
