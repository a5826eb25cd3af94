#include "lab/scan/Progress.h"

#include <cstdio>
#include <string>
#include <unistd.h>

namespace rosin::scan
{

namespace
{
using Clock = std::chrono::steady_clock;
constexpr auto kTerminalInterval = std::chrono::milliseconds(250);
constexpr auto kLogInterval = std::chrono::seconds(10);

std::string clockText(double seconds)
{
    const auto s = static_cast<long>(seconds + 0.5);
    char text[32];
    if (s >= 3600)
        std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else
        std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    return text;
}
} // namespace

bool stderrIsTerminal() noexcept
{
    return isatty(STDERR_FILENO) != 0;
}

Progress::Progress(std::ostream& err, std::size_t total, std::size_t alreadyDone, bool enabled)
    : err_(err), total_(total), resumed_(alreadyDone), done_(alreadyDone), enabled_(enabled),
      terminal_(stderrIsTerminal()), start_(Clock::now()), lastDraw_(start_)
{
}

double Progress::seconds() const
{
    return std::chrono::duration<double>(Clock::now() - start_).count();
}

void Progress::add(std::size_t n)
{
    done_ += n;
    tick();
}

void Progress::tick()
{
    const auto now = Clock::now();
    if (enabled_ &&
        now - lastDraw_ >= (terminal_ ? Clock::duration(kTerminalInterval) : Clock::duration(kLogInterval)))
    {
        lastDraw_ = now;
        draw(false);
    }
}

void Progress::draw(bool final)
{
    const double elapsed = seconds();
    const double computed = static_cast<double>(done_ - resumed_);
    const double rate = elapsed > 0.0 ? computed / elapsed : 0.0;
    char line[160];
    if (final)
        std::snprintf(line, sizeof line, "scan: %zu/%zu cells, %zu computed in %.1f s (%.1f cells/s)", done_,
                      total_, done_ - resumed_, elapsed, rate);
    else
    {
        const double left = rate > 0.0 ? static_cast<double>(total_ - done_) / rate : 0.0;
        std::snprintf(line, sizeof line, "scan: %zu/%zu cells (%.0f %%), %.1f cells/s, %s left", done_,
                      total_,
                      total_ > 0 ? 100.0 * static_cast<double>(done_) / static_cast<double>(total_) : 100.0,
                      rate, rate > 0.0 ? clockText(left).c_str() : "?");
    }
    // On a terminal the line is redrawn in place; the spaces clear a longer previous line.
    if (terminal_)
        err_ << '\r' << line << "    " << (final ? "\n" : "") << std::flush;
    else
        err_ << line << "\n" << std::flush;
}

void Progress::finish(bool complete)
{
    if (!enabled_)
        return;
    draw(true);
    if (!complete)
        err_ << "scan: interrupted after the running cells finished\n";
}

} // namespace rosin::scan
