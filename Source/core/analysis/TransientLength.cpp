#include "core/analysis/TransientLength.h"

#include <algorithm>
#include <cmath>

namespace rosin::analysis
{

const char* transientFailureName(TransientFailure failure) noexcept
{
    switch (failure)
    {
    case TransientFailure::None:
        return "none";
    case TransientFailure::MultipleSlipping:
        return "multiple-slipping";
    case TransientFailure::ProlongedSticking:
        return "prolonged-sticking";
    }
    return "none";
}

TransientLength measureTransient(const std::vector<SlipEpisode>& episodes, double P,
                                 const TransientOptions& o)
{
    TransientLength r;
    if (episodes.empty() || !(P > 0.0))
        return r;
    r.slipped = true;
    r.firstSlip = episodes.front().onset;
    const std::size_t lastOnset = episodes.back().onset;
    const std::size_t end = o.windowEnd > lastOnset ? o.windowEnd : lastOnset;
    r.insufficientData = static_cast<double>(end - r.firstSlip) < o.capPeriods * P;

    const std::size_t intervals = episodes.size() - 1;
    auto interval = [&](std::size_t i)
    { return static_cast<double>(episodes[i + 1].onset - episodes[i].onset); };
    auto helmholtz = [&](std::size_t i)
    {
        const bool period = std::abs(interval(i) - P) / P < o.tolerance;
        const bool shortSlip =
            o.maxSlipDuration <= 0.0 || static_cast<double>(episodes[i].duration) < o.maxSlipDuration;
        return period && shortSlip;
    };

    // The final run of Helmholtz periods, broken if the string stopped slipping before the window's end.
    const double finalGap = static_cast<double>(end - lastOnset);
    const bool lasts = finalGap <= P * (1.0 + o.tolerance);
    std::size_t runStart = intervals; // index of the first interval of the final run
    while (lasts && runStart > 0 && helmholtz(runStart - 1))
        --runStart;
    const std::size_t runLength = lasts ? intervals - runStart : 0;
    const bool found = runLength >= static_cast<std::size_t>(std::max(1, o.minRunPeriods));
    if (found)
    {
        r.helmholtzStart = episodes[runStart].onset;
        const double periods = static_cast<double>(*r.helmholtzStart - r.firstSlip) / P;
        if (periods < o.capPeriods)
            r.periods = periods;
    }

    // The failure type: where the time before t_H (or all of it, if never) went.
    const std::size_t irregular = found ? runStart : intervals;
    for (std::size_t i = 0; i < irregular; ++i)
    {
        const double d = interval(i);
        if (d < P * (1.0 - o.tolerance))
            r.shortIntervalPeriods += d / P;
        else if (d > P * (1.0 + o.tolerance))
            r.longIntervalPeriods += d / P;
    }
    if (!lasts)
        r.longIntervalPeriods += finalGap / P;
    if (r.shortIntervalPeriods > 0.0 || r.longIntervalPeriods > 0.0)
        r.failure = r.shortIntervalPeriods >= r.longIntervalPeriods ? TransientFailure::MultipleSlipping
                                                                    : TransientFailure::ProlongedSticking;
    return r;
}

TransientLength measureTransient(const std::vector<std::size_t>& onsets, double periodSamples,
                                 const TransientOptions& options)
{
    std::vector<SlipEpisode> episodes;
    episodes.reserve(onsets.size());
    for (const std::size_t k : onsets)
        episodes.push_back({k, 0, true});
    TransientOptions o = options;
    o.maxSlipDuration = 0.0; // no durations to check
    return measureTransient(episodes, periodSamples, o);
}

double steadyPeriod(const std::vector<std::size_t>& onsets, std::size_t intervals)
{
    if (onsets.size() < 2 || intervals == 0)
        return 0.0;
    const std::size_t count = std::min(intervals, onsets.size() - 1);
    std::vector<double> d;
    for (std::size_t i = onsets.size() - count; i < onsets.size(); ++i)
        d.push_back(static_cast<double>(onsets[i] - onsets[i - 1]));
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    double median = d[d.size() / 2];
    if (d.size() % 2 == 0)
        median = 0.5 * (median +
                        *std::max_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2)));
    return median;
}

} // namespace rosin::analysis
