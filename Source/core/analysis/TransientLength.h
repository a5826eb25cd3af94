#pragma once
// How long a bowed attack takes to settle into Helmholtz motion ([Notes §7.3]; [Galluzzo2017] Figs. 5-8):
// counted in periods from the first slip to the start of the Helmholtz motion that then lasts, with a cap
// (20 periods in [Galluzzo2017]) above which the pixel is "not reached".
//
// An interval between successive slip onsets is a Helmholtz period when |Delta_i - P|/P < tolerance (and,
// if durations are known and a limit given, its slip was shorter than ~2 beta P). One extra slip splits a
// period into two short intervals, so "exactly one slip per period" is part of the interval test.
// t_H is the first onset of the final unbroken run of Helmholtz periods, if that run has at least
// minRunPeriods intervals and lasts to the end of the analysed window. Sample indices; P in samples.
#include <cstddef>
#include <optional>
#include <vector>

#include "core/analysis/SlipOnsets.h"

namespace rosin::analysis
{

/// What went wrong before Helmholtz motion took over ([Notes §7.3] step 6).
enum class TransientFailure
{
    None,             ///< no interval out of tolerance before t_H: a perfect start (or only long slips)
    MultipleSlipping, ///< extra slips: intervals shorter than P (bow too fast for the force)
    ProlongedSticking ///< missing slips: intervals longer than P ("creak", force too high)
};

/// "none", "multiple-slipping", "prolonged-sticking".
const char* transientFailureName(TransientFailure failure) noexcept;

struct TransientOptions
{
    double tolerance = 0.05;  ///< |Delta - P|/P below this is a Helmholtz period ([Notes §7.3])
    int minRunPeriods = 5;    ///< the Helmholtz run must have at least this many intervals ([Notes §7.3])
    double capPeriods = 20.0; ///< transients this long or longer are "not reached" ([Galluzzo2017]: 20)
    /// Longest slip of a Helmholtz period, samples ([Notes §7.3]: < 2 beta P, "loose"); 0 = not checked
    /// (always the case for onsets from the bridge force, which carry no durations).
    double maxSlipDuration = 0.0;
    /// End of the analysed window, samples (0 = the last onset). A final gap longer than a Helmholtz period
    /// means the motion did not last: the string stopped slipping.
    std::size_t windowEnd = 0;
};

struct TransientLength
{
    bool slipped = false;                      ///< at least one slip
    std::size_t firstSlip = 0;                 ///< t1, samples
    std::optional<std::size_t> helmholtzStart; ///< t_H, samples (empty if no lasting Helmholtz run)
    /// (t_H - t1)/P, periods; empty when not reached: no lasting run, or one starting at or after the cap.
    std::optional<double> periods;
    /// Fewer than capPeriods periods of data after t1: [Galluzzo2017]'s "x" pixel (unsuccessful measurement).
    bool insufficientData = false;
    TransientFailure failure = TransientFailure::None;
    double shortIntervalPeriods = 0.0; ///< time before t_H spent in intervals < P(1 - tol), periods
    double longIntervalPeriods = 0.0;  ///< time before t_H spent in intervals > P(1 + tol), periods
};

/// From slip episodes (durations used if options.maxSlipDuration > 0).
TransientLength measureTransient(const std::vector<SlipEpisode>& episodes, double periodSamples,
                                 const TransientOptions& options = {});
/// From onsets alone (e.g. slipOnsetsFromBridgeForce).
TransientLength measureTransient(const std::vector<std::size_t>& onsets, double periodSamples,
                                 const TransientOptions& options = {});

/// The steady period, samples: the median of the last `intervals` onset intervals (0 if none). Pass it as
/// P when the pitch is known to be flattened (a stopped string on a body) rather than nominal.
double steadyPeriod(const std::vector<std::size_t>& onsets, std::size_t intervals = 10);

} // namespace rosin::analysis
