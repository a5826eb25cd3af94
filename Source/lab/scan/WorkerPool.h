#pragma once
// Computes a list of cells on several threads, each with its own CellRunner (one prepared voice per thread).
// Each thread's runner takes the next cell from a shared counter whenever one of its SIMD lanes is free, so
// the split varies from run to run, but every cell is computed independently and deterministically: the rows
// do not depend on it. Finished rows are handed to the owning thread through take(), which is where they are
// written, counted and (MPI) sent.
#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "lab/scan/JobPool.h"
#include "lab/scan/ScanSpec.h"

namespace rosin::scan
{

struct FinishedCell
{
    std::size_t cell = 0;
    std::string row; ///< formatted, without newline
};

/// rosin scan's cells on the lab's JobPool, one CellRunner per thread.
class WorkerPool
{
  public:
    /// Starts min(threads, cells) threads (at least one if there are cells). `spec` must outlive the pool.
    WorkerPool(const ScanSpec& spec, std::vector<std::size_t> cells, unsigned threads);

    /// Rows finished since the last call, waiting up to `wait` for the first. Rethrows a worker's exception.
    std::vector<FinishedCell> take(std::chrono::milliseconds wait);
    /// No new cells are started; running ones finish and are still reported.
    void stop() noexcept { pool_.stop(); }
    /// Every thread has exited and every row has been taken. Rethrows a worker's exception.
    bool finished() { return pool_.finished(); }

  private:
    JobPool<std::string> pool_; ///< a cell's formatted row, without newline
};

/// Takes rows until the pool has finished, on the calling thread: each row goes to `sink`; between waits of
/// up to `wait`, `idle` runs (progress, MPI polling) and `shouldStop` is asked whether to stop the pool.
void drainPool(WorkerPool& pool, const std::function<void(const FinishedCell&)>& sink,
               const std::function<bool()>& shouldStop, const std::function<void()>& idle,
               std::chrono::milliseconds wait);

/// The default thread count: std::thread::hardware_concurrency(), at least 1.
unsigned defaultThreadCount() noexcept;

} // namespace rosin::scan
