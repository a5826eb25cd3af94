#include "CellRunner.h"

#include "CellAnalysis.h"
#include "TrialProtocol.h"

namespace rosin::scan
{

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
    for (std::size_t k = 0; k < protocol.samples(); ++k)
        samples_.push_back(voice_.step(protocol.at(k)));
    TrialContext context;
    context.kind = spec_.kind;
    context.cell = settings;
    context.sampleRate = spec_.sampleRate;
    context.periodSamples = periodSamples_;
    context.rampEnd = protocol.rampEnd();
    return analyseTrial(samples_, context);
}

} // namespace rosin::scan
