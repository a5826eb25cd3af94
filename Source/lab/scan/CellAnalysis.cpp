#include "CellAnalysis.h"

#include <algorithm>
#include <cmath>

#include "lab/FirstSlip.h"
#include "lab/RegimeClassifier.h"
#include "lab/SlipOnsets.h"

namespace rosin::scan
{

namespace
{
lab::AnalysisWindow steadyWindow(std::size_t n, const TrialContext& c)
{
    const double minimum = kSteadyWindowPeriods * c.periodSamples;
    double length = minimum;
    if (c.kind == ScanKind::Schelleng)
        length = std::max(minimum, 0.5 * static_cast<double>(n - std::min(n, c.rampEnd)));
    const auto samples = static_cast<std::size_t>(std::min(static_cast<double>(n), std::round(length)));
    return {n - samples, n};
}

void addFirstSlip(const std::vector<physics::VoiceSample>& samples, const TrialContext& c, CellResult& r)
{
    const auto [force, sticking] = lab::forceAndState(samples);
    lab::FirstSlipOptions o;
    o.sampleRate = c.sampleRate;
    o.beta = c.cell.beta;
    o.bowForce = c.cell.force;
    o.periodSeconds = c.periodSamples / c.sampleRate;
    const lab::FirstSlip first = lab::firstSlipFromState(force, sticking, o);
    if (!first.found)
        return;
    r.muStatic = first.muStatic;
    r.jump = first.jump;
    r.firstSlipTime = first.firstSlipTime;
}

// The period to measure the transient against: the measured one when `steady` is one flyback per period
// near the nominal pitch, else the nominal one.
double transientPeriod(const lab::RegimeAnalysis& steady, double nominal)
{
    const bool helmholtzType =
        steady.regime == lab::Regime::Helmholtz || steady.regime == lab::Regime::SMotion;
    const bool near =
        std::abs(steady.measuredPeriod / nominal - 1.0) < lab::regime_thresholds::kPeriodTolerance;
    return helmholtzType && steady.slipsPerCycle == 1 && near ? steady.measuredPeriod : nominal;
}
// Reference 7.3 on the flyback episodes, judged over the first 2 x cap periods after the first slip: the
// Helmholtz run must start within the cap and last to the end of that window. The bow keeps accelerating
// (Guettler) and F_min grows with the bow speed, so "lasting to the end of the trial" would make the
// transient depend on the trial's length; this window does not, as long as the trial covers it. For the same
// reason the period it is counted in is measured over the window's second half, not at the trial's end,
// where a faster bow flattens the string differently (an early-ended trial would count in another period).
void addTransient(const std::vector<physics::VoiceSample>& samples, const TrialContext& c, CellResult& r)
{
    const double nominal = c.periodSamples;
    auto episodes = lab::fullFlybacksOnly(lab::slipEpisodesFromVoice(samples), c.cell.beta, kFlybackShare);
    if (episodes.empty())
        return;
    const double window = static_cast<double>(episodes.front().onset) + 2.0 * kTransientCapPeriods * nominal;
    const auto end =
        static_cast<std::size_t>(std::min(static_cast<double>(samples.size()), std::ceil(window)));
    std::erase_if(episodes, [end](const lab::SlipEpisode& e) { return e.onset >= end; });
    const auto half = static_cast<std::size_t>(std::round(kTransientCapPeriods * nominal));
    const auto late = lab::classifyFromVoice(samples, nominal, {end - std::min(end, half), end});
    lab::TransientOptions t;
    t.capPeriods = kTransientCapPeriods;
    t.windowEnd = end;
    const auto transient = lab::measureTransient(episodes, transientPeriod(late, nominal), t);
    // Fewer than cap periods of trial after the first slip: seed 001's "x" pixel, not a result.
    if (!transient.insufficientData)
        r.transientPeriods = transient.periods;
    r.failure = transient.failure;
}

// The bridge-force variant of addTransient: onsets found in the force, the window from the first of them.
void addTransientFromForce(const std::vector<double>& force, const TrialContext& c, CellResult& r)
{
    const double nominal = c.periodSamples;
    auto onsets = lab::slipOnsetsFromBridgeForce(force, nominal);
    if (onsets.empty())
        return;
    const double window = static_cast<double>(onsets.front()) + 2.0 * kTransientCapPeriods * nominal;
    const auto end = static_cast<std::size_t>(std::min(static_cast<double>(force.size()), std::ceil(window)));
    std::erase_if(onsets, [end](std::size_t o) { return o >= end; });
    const auto half = static_cast<std::size_t>(std::round(kTransientCapPeriods * nominal));
    const auto late = lab::classifyFromBridgeForce(force, nominal, {end - std::min(end, half), end});
    lab::TransientOptions t;
    t.capPeriods = kTransientCapPeriods;
    t.windowEnd = end;
    const auto transient = lab::measureTransient(onsets, transientPeriod(late, nominal), t);
    if (!transient.insufficientData)
        r.transientPeriods = transient.periods;
    r.failure = transient.failure;
}
} // namespace

CellResult analyseTrial(const std::vector<physics::VoiceSample>& samples, const TrialContext& c)
{
    CellResult r;
    r.cell = c.cell.cell;
    r.beta = c.cell.beta;
    r.bowForce = c.cell.force;
    r.second = c.cell.second;
    addFirstSlip(samples, c, r);

    const auto window = steadyWindow(samples.size(), c);
    lab::RegimeAnalysis steady;
    if (c.classification == Classification::BridgeForce)
        steady =
            lab::classifyFromBridgeForce(lab::forceAndState(samples).bridgeForce, c.periodSamples, window);
    else
        steady = lab::classifyFromVoice(samples, c.periodSamples, window);
    r.regime = steady.regime;
    if (steady.onsetCount >= 2)
        r.slipsPerPeriod = steady.slipsPerPeriod;
    if (steady.measuredPeriod > 0.0)
        r.pitchCents = steady.pitchCents;

    if (c.kind == ScanKind::Schelleng)
        addTransient(samples, c, r); // a Schelleng row's transient is informative only; kept from the state
    else if (c.classification == Classification::BridgeForce)
        addTransientFromForce(lab::forceAndState(samples).bridgeForce, c, r);
    else
        addTransient(samples, c, r);
    return r;
}

} // namespace rosin::scan
