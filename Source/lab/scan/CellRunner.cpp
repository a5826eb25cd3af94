#include "CellRunner.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "CellAnalysis.h"
#include "TrialProtocol.h"
#include "lab/RegimeClassifier.h"
#include "lab/SlipOnsets.h"

namespace rosin::scan
{

namespace
{
// How often (periods) a Guettler trial looks for its first full flyback while it runs.
constexpr double kFlybackCheckPeriods = 5.0;

// Onset of the first full flyback so far. Episodes only grow, so one found now is the first of the whole
// trial.
std::optional<std::size_t> firstFullFlyback(const std::vector<physics::VoiceSample>& samples, double beta)
{
    const auto episodes = lab::fullFlybacksOnly(lab::slipEpisodesFromVoice(samples), beta, kFlybackShare);
    if (episodes.empty())
        return std::nullopt;
    return episodes.front().onset;
}

// Samples after the first full flyback that the analysis reads: 2 x cap periods of the period it measures
// against, which is within the classifier's tolerance of the nominal one (CellAnalysis.h).
std::size_t transientWindowSamples(double nominalPeriod)
{
    const double longest = nominalPeriod * (1.0 + lab::regime_thresholds::kPeriodTolerance);
    return static_cast<std::size_t>(std::ceil(2.0 * kTransientCapPeriods * longest)) + 1;
}

} // namespace

CellRunner::CellRunner(const ScanSpec& spec) : spec_(spec)
{
    voice_.prepare(voiceConfig(spec.model), frictionLaw(spec.model), spec.sampleRate);
    lanes_.prepare(voice_,
                   physics::makeLaneFriction([&spec] { return frictionLaw(spec.model); }, spec.sampleRate));
    periodSamples_ = spec.sampleRate / spec.model.string.fundamental();
}

void CellRunner::useBeta(double beta)
{
    if (beta == lanesBeta_)
    {
        lanes_.reset();
        return;
    }
    voice_.setBowPosition(beta, 1.0);
    lanes_.retune(voice_);
    lanesBeta_ = beta;
}

std::vector<CellResult> CellRunner::run(const std::vector<std::size_t>& cells)
{
    const std::size_t n = cells.size();
    if (n == 0 || n > kBatch)
        throw std::invalid_argument("CellRunner::run: 1 to " + std::to_string(kBatch) + " cells at a time");
    std::vector<CellSettings> settings;
    std::vector<TrialProtocol> protocols;
    for (const std::size_t cell : cells)
    {
        settings.push_back(cellSettings(spec_, cell));
        protocols.emplace_back(spec_, settings.back());
        if (settings.back().beta != settings.front().beta)
            throw std::invalid_argument("CellRunner::run: the cells of a batch must share one beta");
    }
    useBeta(settings.front().beta);

    std::array<std::size_t, physics::kLanes> end{};
    std::array<bool, physics::kLanes> looking{};
    for (std::size_t l = 0; l < n; ++l)
    {
        samples_[l].clear();
        samples_[l].reserve(protocols[l].samples());
        end[l] = protocols[l].samples();
        looking[l] = spec_.kind == ScanKind::Guettler && spec_.endAfterTransient;
    }
    const auto checkInterval = static_cast<std::size_t>(std::ceil(kFlybackCheckPeriods * periodSamples_));
    physics::LaneBowInput in; // lanes beyond n stay at rest
    std::array<physics::VoiceSample, physics::kLanes> out;
    std::size_t last = *std::max_element(end.begin(), end.begin() + n);
    for (std::size_t k = 0; k < last; ++k)
    {
        for (std::size_t l = 0; l < n; ++l)
        {
            const physics::BowInput b = protocols[l].at(std::min(k, end[l] - 1));
            in.bowForce[l] = b.bowForce;
            in.bowVelocity[l] = b.bowVelocity;
        }
        lanes_.step(in, out);
        bool ended = false;
        for (std::size_t l = 0; l < n; ++l)
        {
            if (k >= end[l])
                continue;
            samples_[l].push_back(out[l]);
            if (!looking[l] || (k + 1) % checkInterval != 0)
                continue;
            if (const auto onset = firstFullFlyback(samples_[l], settings[l].beta))
            {
                end[l] = std::min(end[l], *onset + transientWindowSamples(periodSamples_));
                looking[l] = false;
                ended = true;
            }
        }
        if (ended)
            last = *std::max_element(end.begin(), end.begin() + n);
    }

    std::vector<CellResult> results;
    for (std::size_t l = 0; l < n; ++l)
    {
        TrialContext context;
        context.kind = spec_.kind;
        context.cell = settings[l];
        context.sampleRate = spec_.sampleRate;
        context.periodSamples = periodSamples_;
        context.rampEnd = protocols[l].rampEnd();
        results.push_back(analyseTrial(samples_[l], context));
    }
    return results;
}

std::vector<std::vector<std::size_t>> batchesOf(const ScanSpec& spec, const std::vector<std::size_t>& cells)
{
    std::vector<std::vector<std::size_t>> batches;
    for (const std::size_t cell : cells)
    {
        const std::size_t beta = coordinatesOf(spec, cell).beta;
        if (batches.empty() || batches.back().size() == CellRunner::kBatch ||
            coordinatesOf(spec, batches.back().front()).beta != beta)
            batches.emplace_back();
        batches.back().push_back(cell);
    }
    return batches;
}

} // namespace rosin::scan
