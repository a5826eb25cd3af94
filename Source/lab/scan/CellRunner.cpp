#include "lab/scan/CellRunner.h"

#include <algorithm>
#include <stdexcept>

#include "lab/scan/CellAnalysis.h"
#include "lab/scan/TrialEnd.h"
#include "lab/scan/TrialProtocol.h"

namespace rosin::scan
{

struct CellRunner::Lane
{
    int index = 0;
    std::optional<std::size_t> cell; ///< empty: free
    CellSettings settings;
    std::optional<TrialProtocol> protocol;
    std::optional<TrialEnd> end;
    std::size_t k = 0; ///< the trial's next sample
};

CellRunner::CellRunner(const ScanSpec& spec, bool skipStuckStarts) : spec_(spec)
{
    voice_.prepare(voiceConfig(spec.model), frictionLaw(spec.model), spec.sampleRate);
    lanes_.prepare(voice_,
                   physics::makeLaneFriction([&spec] { return frictionLaw(spec.model); }, spec.sampleRate));
    periodSamples_ = spec.sampleRate / spec.model.string.fundamental();
    skipStuckStarts_ =
        skipStuckStarts && spec.kind == ScanKind::Guettler && lanes_.friction().restingLimit(1.0).has_value();
}

void CellRunner::useBeta(double beta)
{
    if (beta == lanesBeta_)
        return;
    voice_.setBowPosition(beta, 1.0);
    lanes_.retune(voice_);
    if (skipStuckStarts_)
        rampStart_.prepare(voice_, spec_.sampleRate);
    lanesBeta_ = beta;
}

void CellRunner::start(Lane& lane, std::size_t cell)
{
    lane.cell = cell;
    lane.settings = cellSettings(spec_, cell);
    lane.protocol.emplace(spec_, lane.settings);
    // Schelleng trials always run whole: their regime is judged at the end.
    const GuettlerTrialEnd rule = spec_.kind == ScanKind::Guettler ? spec_.trialEnd : GuettlerTrialEnd::Whole;
    lane.end.emplace(rule, lane.settings.beta, periodSamples_, lane.protocol->samples());
    lane.k = 0;
    auto& samples = samples_[static_cast<std::size_t>(lane.index)];
    samples.clear();
    samples.reserve(lane.protocol->samples());
    lanes_.resetLane(lane.index);
    if (skipStuckStarts_)
        skipStuckStart(lane, samples);
}

// The samples in which the trial certainly sticks, scaled from the unit start (RampStart.h).
void CellRunner::skipStuckStart(Lane& lane, std::vector<physics::VoiceSample>& samples)
{
    const double a = lane.settings.second, limit = *lanes_.friction().restingLimit(lane.settings.force);
    const std::size_t skipped = rampStart_.skippable(a, limit, lane.protocol->samples());
    if (skipped == 0)
        return;
    rampStart_.start(lanes_, lane.index, a, skipped);
    for (; lane.k < skipped; ++lane.k)
    {
        const physics::VoiceSample& unit = rampStart_.unitSample(lane.k);
        const double vb = lane.protocol->at(lane.k).bowVelocity;
        samples.push_back({a * unit.bridgeForce, vb, a * unit.frictionForce, vb, 0.0, true});
        lane.end->add(samples.back());
    }
}

CellResult CellRunner::finish(const Lane& lane) const
{
    TrialContext context;
    context.kind = spec_.kind;
    context.cell = lane.settings;
    context.sampleRate = spec_.sampleRate;
    context.periodSamples = periodSamples_;
    context.rampEnd = lane.protocol->rampEnd();
    context.classification = spec_.classification;
    return analyseTrial(samples_[static_cast<std::size_t>(lane.index)], context);
}

// Starts the next cells on the free lanes; false once no lane is busy. A cell of another beta waits in
// `waiting` until every lane is free, then the lanes are retuned for it.
bool CellRunner::fillFreeLanes(Lanes& lanes, const CellSource& next, std::optional<std::size_t>& waiting,
                               bool& more)
{
    bool busy = std::any_of(lanes.begin(), lanes.end(), [](const Lane& l) { return l.cell.has_value(); });
    for (Lane& lane : lanes)
    {
        if (lane.cell || !more)
            continue;
        if (!waiting && !(waiting = next()))
        {
            more = false;
            break;
        }
        const double beta = cellSettings(spec_, *waiting).beta;
        if (beta != lanesBeta_ && busy)
            break;
        useBeta(beta);
        start(lane, *waiting);
        waiting.reset();
        busy = true;
    }
    return busy;
}

// One sample of every lane; a lane whose trial ends hands its result to `done` and is free again.
void CellRunner::stepLanes(Lanes& lanes, const CellSink& done)
{
    physics::LaneBowInput in; // free lanes get no bow
    for (const Lane& lane : lanes)
    {
        const auto l = static_cast<std::size_t>(lane.index);
        const physics::BowInput b = lane.cell ? lane.protocol->at(lane.k) : physics::BowInput{0.0, 0.0};
        in.bowForce[l] = b.bowForce;
        in.bowVelocity[l] = b.bowVelocity;
    }
    std::array<physics::VoiceSample, physics::kLanes> out;
    lanes_.step(in, out);
    for (Lane& lane : lanes)
    {
        if (!lane.cell)
            continue;
        const auto l = static_cast<std::size_t>(lane.index);
        samples_[l].push_back(out[l]);
        ++lane.k;
        if (lane.end->add(out[l]))
        {
            done(finish(lane));
            lane.cell.reset();
        }
    }
}

void CellRunner::runAll(const CellSource& next, const CellSink& done)
{
    Lanes lanes;
    for (int l = 0; l < physics::kLanes; ++l)
        lanes[static_cast<std::size_t>(l)].index = l;
    std::optional<std::size_t> waiting; // a cell of another beta, taken from `next`
    bool more = true;
    while (fillFreeLanes(lanes, next, waiting, more))
        stepLanes(lanes, done);
}

std::vector<CellResult> CellRunner::run(const std::vector<std::size_t>& cells)
{
    if (cells.empty())
        throw std::invalid_argument("CellRunner::run: no cells");
    for (const std::size_t cell : cells)
        if (cellSettings(spec_, cell).beta != cellSettings(spec_, cells.front()).beta)
            throw std::invalid_argument("CellRunner::run: the cells must share one beta");
    std::size_t taken = 0;
    std::vector<CellResult> results(cells.size());
    runAll([&]() -> std::optional<std::size_t>
           { return taken < cells.size() ? std::optional(cells[taken++]) : std::nullopt; },
           [&](const CellResult& r)
           {
               const auto at = std::find(cells.begin(), cells.end(), r.cell) - cells.begin();
               results[static_cast<std::size_t>(at)] = r;
           });
    return results;
}

} // namespace rosin::scan
