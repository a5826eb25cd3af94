#include "lab/scan/CellAnalysis.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/FirstSlip.h"
#include "core/analysis/RegimeClassifier.h"
#include "core/analysis/SlipOnsets.h"

namespace rosin::scan
{

namespace
{
analysis::AnalysisWindow steadyWindow(std::size_t n, const TrialContext& c)
{
    const double minimum = kSteadyWindowPeriods * c.periodSamples;
    double length = minimum;
    if (c.kind == ScanKind::Schelleng)
        length = std::max(minimum, 0.5 * static_cast<double>(n - std::min(n, c.rampEnd)));
    const auto samples = static_cast<std::size_t>(std::min(static_cast<double>(n), std::round(length)));
    return {n - samples, n};
}

void addFirstSlip(const analysis::ForceAndState& trace, const TrialContext& c, CellResult& r)
{
    const auto& [force, sticking] = trace;
    analysis::FirstSlipOptions o;
    o.sampleRate = c.sampleRate;
    o.beta = c.cell.beta;
    o.bowForce = c.cell.force;
    o.periodSeconds = c.periodSamples / c.sampleRate;
    const analysis::FirstSlip first = analysis::firstSlipFromState(force, sticking, o);
    if (!first.found)
        return;
    r.muStatic = first.muStatic;
    r.jump = first.jump;
    r.firstSlipTime = first.firstSlipTime;
}

// The period to measure the transient against: the measured one when `steady` is one flyback per period
// near the nominal pitch, else the nominal one.
double transientPeriod(const analysis::RegimeAnalysis& steady, double nominal)
{
    const bool helmholtzType =
        steady.regime == analysis::Regime::Helmholtz || steady.regime == analysis::Regime::SMotion;
    const bool near =
        std::abs(steady.measuredPeriod / nominal - 1.0) < analysis::regime_thresholds::kPeriodTolerance;
    return helmholtzType && steady.slipsPerCycle == 1 && near ? steady.measuredPeriod : nominal;
}
// [Notes §7.3] on the slips (flyback episodes, or onsets found in the bridge force), judged over the first
// 2 x cap periods after the first slip: the Helmholtz run must start within the cap and last to the end of
// that window. The bow keeps accelerating (Guettler) and F_min grows with the bow speed, so "lasting to the
// end of the trial" would make the transient depend on the trial's length; this window does not, as long as
// the trial covers it. For the same reason the period it is counted in is measured over the window's second
// half (by `classifyLate`), not at the trial's end, where a faster bow flattens the string differently.
template <typename Slips, typename OnsetOf, typename ClassifyLate>
void addTransientInWindow(Slips slips, OnsetOf onsetOf, std::size_t samples, const TrialContext& c,
                          ClassifyLate classifyLate, CellResult& r)
{
    if (slips.empty())
        return;
    const double nominal = c.periodSamples;
    const double window = static_cast<double>(onsetOf(slips.front())) + 2.0 * kTransientCapPeriods * nominal;
    const auto end = static_cast<std::size_t>(std::min(static_cast<double>(samples), std::ceil(window)));
    std::erase_if(slips, [&](const auto& s) { return onsetOf(s) >= end; });
    const auto half = static_cast<std::size_t>(std::round(kTransientCapPeriods * nominal));
    const analysis::RegimeAnalysis late =
        classifyLate(analysis::AnalysisWindow{end - std::min(end, half), end});
    analysis::TransientOptions t;
    t.capPeriods = kTransientCapPeriods;
    t.windowEnd = end;
    const auto transient = analysis::measureTransient(slips, transientPeriod(late, nominal), t);
    // Fewer than cap periods of trial after the first slip: [Galluzzo2017]'s "x" pixel, not a result.
    if (!transient.insufficientData)
        r.transientPeriods = transient.periods;
    r.failure = transient.failure;
}

void addTransient(const std::vector<physics::VoiceSample>& samples, const TrialContext& c, CellResult& r)
{
    addTransientInWindow(
        analysis::fullFlybacksOnly(analysis::slipEpisodesFromVoice(samples), c.cell.beta, kFlybackShare),
        [](const analysis::SlipEpisode& e) { return e.onset; }, samples.size(), c,
        [&](analysis::AnalysisWindow w) { return analysis::classifyFromVoice(samples, c.periodSamples, w); },
        r);
}

// The bridge-force variant: onsets found in the force, as a measurement's are.
void addTransientFromForce(const std::vector<double>& force, const TrialContext& c, CellResult& r)
{
    addTransientInWindow(
        analysis::slipOnsetsFromBridgeForce(force, c.periodSamples), [](std::size_t o) { return o; },
        force.size(), c,
        [&](analysis::AnalysisWindow w)
        { return analysis::classifyFromBridgeForce(force, c.periodSamples, w); },
        r);
}
} // namespace

CellResult analyseTrial(const std::vector<physics::VoiceSample>& samples, const TrialContext& c)
{
    CellResult r;
    r.cell = c.cell.cell;
    r.beta = c.cell.beta;
    r.bowForce = c.cell.force;
    r.second = c.cell.second;
    const analysis::ForceAndState trace =
        analysis::forceAndState(samples); // once: the first slip and the force analyses
    addFirstSlip(trace, c, r);

    const auto window = steadyWindow(samples.size(), c);
    analysis::RegimeAnalysis steady;
    if (c.classification == Classification::BridgeForce)
        steady = analysis::classifyFromBridgeForce(trace.bridgeForce, c.periodSamples, window);
    else
        steady = analysis::classifyFromVoice(samples, c.periodSamples, window);
    r.regime = steady.regime;
    if (steady.onsetCount >= 2)
        r.slipsPerPeriod = steady.slipsPerPeriod;
    if (steady.measuredPeriod > 0.0)
        r.pitchCents = steady.pitchCents;

    if (c.kind == ScanKind::Schelleng)
        addTransient(samples, c, r); // a Schelleng row's transient is informative only; kept from the state
    else if (c.classification == Classification::BridgeForce)
        addTransientFromForce(trace.bridgeForce, c, r);
    else
        addTransient(samples, c, r);
    return r;
}

} // namespace rosin::scan
