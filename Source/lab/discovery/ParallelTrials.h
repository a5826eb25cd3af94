#pragma once
// Trials computed on several threads through the lab's one thread pool (scan::JobPool), each thread with its
// own worker (for a simulation: one prepared voice). Results reach the calling thread, which alone writes
// files, in whatever order they finish. Each job is computed independently and deterministically, so what is
// written does not depend on the split.
#include <chrono>
#include <cstddef>
#include <functional>
#include <vector>

#include "lab/scan/JobPool.h"

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
    using Pool = scan::JobPool<Result>;
    Pool pool(jobs, threads,
              [&makeWorker](const typename Pool::Next& next, const typename Pool::Deliver& deliver)
              {
                  auto compute = makeWorker();
                  while (const auto job = next())
                      deliver(*job, compute(*job));
              });
    while (!pool.finished()) // the pool's destructor waits for every thread, also when this throws
        for (auto& [job, result] : pool.take(std::chrono::seconds(1)))
            take(job, std::move(result));
}

} // namespace rosin::discovery
