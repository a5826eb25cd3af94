#include "cli/LoopOutput.h"

#include <filesystem>

#include "cli/CommandLine.h"
#include "core/config/AtomicFile.h"
#include "core/config/ConfigError.h"
#include "lab/scan/Figures.h"

namespace rosin::cli
{

void parseLoopInterval(const std::string& text, LoopRequest& request)
{
    const auto colon = text.find(':');
    const char* expected = "A:B in seconds with 0 <= A < B";
    if (colon == std::string::npos)
        throw config::ConfigError("--loop-interval", "", expected, "\"" + text + "\"");
    const double a = parseNumber("--loop-interval", text.substr(0, colon));
    const double b = parseNumber("--loop-interval", text.substr(colon + 1));
    if (!(a >= 0.0) || !(b > a))
        throw config::ConfigError("--loop-interval", "", expected, "\"" + text + "\"");
    request.from = a;
    request.to = b;
}

analysis::HysteresisLoop makeLoop(const LoopRequest& request, double totalSeconds, double sampleRate)
{
    const double to = request.to.value_or(totalSeconds);
    const double from = request.from.value_or(std::max(0.0, totalSeconds - LoopRequest::kDefaultSeconds));
    if (to > totalSeconds + 0.5 / sampleRate)
        throw config::ConfigError("--loop-interval", "",
                                  "an interval inside the gesture (0 to " + std::to_string(totalSeconds) +
                                      " s)",
                                  std::to_string(from) + ":" + std::to_string(to));
    return analysis::HysteresisLoop(from, to, sampleRate);
}

void writeLoop(const analysis::HysteresisLoop& loop, const LoopRequest& request, const std::string& title,
               std::ostream& out, std::ostream& err)
{
    const std::string csv = std::filesystem::path(request.figure).replace_extension(".csv").string();
    config::writeFileAtomically(csv, loop.csv());
    out << "wrote " << csv << ": " << loop.points().size() << " samples of the friction/velocity loop ("
        << static_cast<int>(100.0 * loop.stickingFraction() + 0.5) << " % sticking, enclosed area "
        << loop.signedArea() << " N m/s in (dv, f))\n";
    out.flush(); // the script writes to the same terminal
    scan::runFigureScript({"loop", csv, "--out", request.figure, "--title", title}, err,
                          "; the loop's samples are in " + csv + "\n");
}

} // namespace rosin::cli
