#include "lab/scan/StopSignal.h"

#include <csignal>

namespace rosin::scan
{

namespace
{
volatile std::sig_atomic_t received = 0;

extern "C" void onStopSignal(int signal)
{
    received = signal;
    std::signal(signal, SIG_DFL);
}
} // namespace

void installStopSignals() noexcept
{
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
}

bool stopSignalled() noexcept
{
    return received != 0;
}

int stopSignal() noexcept
{
    return static_cast<int>(received);
}

} // namespace rosin::scan
