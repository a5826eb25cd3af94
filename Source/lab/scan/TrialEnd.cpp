#include "lab/scan/TrialEnd.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/RegimeClassifier.h"
#include "core/analysis/TransientLength.h"
#include "lab/scan/CellAnalysis.h"

namespace rosin::scan
{

namespace
{
// The periods the analysis may measure a transient against, as shares of the nominal one, and the share of
// such a period an interval may differ by and still be a Helmholtz period ([Notes §7.3]).
constexpr double kLongestPeriod = 1.0 + analysis::regime_thresholds::kPeriodTolerance;
constexpr double kShortestPeriod = 1.0 - analysis::regime_thresholds::kPeriodTolerance;
const double kIntervalTolerance = analysis::TransientOptions{}.tolerance;

bool longerThanAnyPeriod(double interval, double P)
{
    return interval > (1.0 + kIntervalTolerance) * kLongestPeriod * P;
}

bool neverHelmholtz(double interval, double P)
{
    return interval < (1.0 - kIntervalTolerance) * kShortestPeriod * P || longerThanAnyPeriod(interval, P);
}
} // namespace

TrialEnd::TrialEnd(GuettlerTrialEnd rule, double beta, double periodSamples, std::size_t trialSamples)
    : rule_(rule), P_(periodSamples), end_(trialSamples),
      flybacks_(beta, kFlybackShare,
                static_cast<std::size_t>(static_cast<double>(trialSamples) / periodSamples))
{
}

bool TrialEnd::add(const physics::VoiceSample& s)
{
    if (rule_ == GuettlerTrialEnd::Whole)
        return ++samples_ >= end_;
    ++samples_;
    flybacks_.add(s);
    const auto& onsets = flybacks_.onsets();
    if (onsets.size() > onsetsSeen_)
    {
        if (onsetsSeen_ == 0)
        {
            // The analysis reads 2 x cap of its period after t1 (CellAnalysis.cpp addTransient).
            const auto t1 = static_cast<double>(onsets.front());
            const double window = 2.0 * kTransientCapPeriods * kLongestPeriod * P_;
            end_ = std::min(end_, onsets.front() + static_cast<std::size_t>(std::ceil(window)) + 1);
            capReach_ = t1 + kTransientCapPeriods * kLongestPeriod * P_;
            shortestWindowEnd_ = t1 + 2.0 * kTransientCapPeriods * kShortestPeriod * P_;
        }
        else if (rule_ == GuettlerTrialEnd::WhenDecided)
        {
            const double interval = static_cast<double>(onsets.back() - onsets[onsets.size() - 2]);
            missed_ = missed_ || (neverHelmholtz(interval, P_) && pastTheCap(onsets.back()) &&
                                  inEveryWindow(onsets.back()));
        }
        onsetsSeen_ = onsets.size();
    }
    // No full flyback for longer than any Helmholtz period: the interval under way will not be one either,
    // unless a slip that started in time is still to become a full flyback.
    if (rule_ == GuettlerTrialEnd::WhenDecided && !onsets.empty() && pastTheCap(samples_) &&
        inEveryWindow(samples_))
    {
        const auto gap = [&](std::size_t k) { return static_cast<double>(k - onsets.back()); };
        const auto pending = flybacks_.pendingOnset();
        missed_ = missed_ || (longerThanAnyPeriod(gap(samples_), P_) &&
                              (!pending || longerThanAnyPeriod(gap(*pending), P_)));
    }
    return samples_ >= end_ || missed_;
}

// A Helmholtz run starting at or after sample k is at least cap periods of any accepted period after t1.
bool TrialEnd::pastTheCap(std::size_t k) const noexcept
{
    return static_cast<double>(k) >= capReach_;
}

// Sample k is inside the analysis's window for any accepted period (it ends 2 x cap periods after t1).
bool TrialEnd::inEveryWindow(std::size_t k) const noexcept
{
    return static_cast<double>(k) < shortestWindowEnd_;
}

} // namespace rosin::scan
