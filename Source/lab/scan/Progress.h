#pragma once
// The progress line of a scan on stderr: cells done / total, cells per second and the time left, redrawn in
// place at most 4 times a second on a terminal (a log file, e.g. a Slurm job's, gets a plain line every 10 s
// instead), and a final line.
#include <chrono>
#include <cstddef>
#include <ostream>

namespace rosin::scan
{

class Progress
{
  public:
    /// `alreadyDone` cells (resumed) count as done but not in the rate. `enabled` false prints nothing.
    Progress(std::ostream& err, std::size_t total, std::size_t alreadyDone, bool enabled);

    /// n more cells finished; redraws if it is time.
    void add(std::size_t n);
    /// Redraws if it is time (call while waiting).
    void tick();
    /// The final line: "scan: 400/400 cells in 3.1 s (129 cells/s)", or how far an interrupted run got.
    void finish(bool complete);

    std::size_t done() const noexcept { return done_; }
    double seconds() const;

  private:
    void draw(bool final);

    std::ostream& err_;
    std::size_t total_, resumed_, done_;
    bool enabled_, terminal_;
    std::chrono::steady_clock::time_point start_, lastDraw_;
};

/// Whether the process's stderr is a terminal.
bool stderrIsTerminal() noexcept;

} // namespace rosin::scan
