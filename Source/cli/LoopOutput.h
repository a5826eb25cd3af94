#pragma once
// `rosin render --loop FILE.png [--loop-interval A:B]`: the friction/velocity hysteresis loop of a chosen
// interval of the render ([Smith2000] Fig. 2c, [Galluzzo2017] Figs. 20-21), kept as FILE.csv beside the
// figure, which the lab's figure script draws.
#include <optional>
#include <ostream>
#include <string>

#include "core/analysis/HysteresisLoop.h"

namespace rosin::cli
{

struct LoopRequest
{
    std::string figure;             ///< FILE.png
    std::optional<double> from, to; ///< s; absent: the last kDefaultSeconds of the render
    static constexpr double kDefaultSeconds = 0.05;
};

/// Parses "A:B" (seconds, 0 <= A < B); throws ConfigError naming --loop-interval.
void parseLoopInterval(const std::string& text, LoopRequest& request);
/// The recorder for a render of `totalSeconds`; throws ConfigError if the interval lies outside it.
analysis::HysteresisLoop makeLoop(const LoopRequest& request, double totalSeconds, double sampleRate);
/// Writes FILE.csv and draws FILE.png; reports on `out`, warns on `err` if the figure could not be drawn.
void writeLoop(const analysis::HysteresisLoop& loop, const LoopRequest& request, const std::string& title,
               std::ostream& out, std::ostream& err);

} // namespace rosin::cli
