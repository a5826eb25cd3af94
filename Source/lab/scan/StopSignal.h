#pragma once
// SIGINT (Ctrl-C) and SIGTERM (Slurm's time limit, mpirun forwarding) ask a scan to stop: no new cells are
// started, the running ones finish and their rows are kept, and the run can be resumed. The handler then
// restores the default action, so a second signal ends the process at once (the rows already reported are
// safe on disk either way).
namespace rosin::scan
{

/// Installs the handlers (idempotent).
void installStopSignals() noexcept;
/// A stop signal has arrived.
bool stopSignalled() noexcept;
/// The signal number that arrived (0 if none).
int stopSignal() noexcept;

} // namespace rosin::scan
