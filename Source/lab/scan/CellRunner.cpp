#include "CellRunner.h"

#include <cmath>
#include <optional>

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
    periodSamples_ = spec.sampleRate / spec.model.string.fundamental();
}

CellResult CellRunner::run(std::size_t cell)
{
    const CellSettings settings = cellSettings(spec_, cell);
    const TrialProtocol protocol(spec_, settings);
    voice_.reset();
    samples_.clear();
    samples_.reserve(protocol.samples());
    std::size_t end = protocol.samples();
    bool looking = spec_.kind == ScanKind::Guettler && spec_.endAfterTransient;
    const auto checkInterval = static_cast<std::size_t>(std::ceil(kFlybackCheckPeriods * periodSamples_));
    for (std::size_t k = 0; k < end; ++k)
    {
        samples_.push_back(voice_.step(protocol.at(k)));
        if (!looking || (k + 1) % checkInterval != 0)
            continue;
        if (const auto onset = firstFullFlyback(samples_, settings.beta))
        {
            end = std::min(end, *onset + transientWindowSamples(periodSamples_));
            looking = false;
        }
    }
    TrialContext context;
    context.kind = spec_.kind;
    context.cell = settings;
    context.sampleRate = spec_.sampleRate;
    context.periodSamples = periodSamples_;
    context.rampEnd = protocol.rampEnd();
    return analyseTrial(samples_, context);
}

} // namespace rosin::scan
