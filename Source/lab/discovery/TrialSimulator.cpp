#include "lab/discovery/TrialSimulator.h"

#include <stdexcept>

#include "lab/scan/TrialProtocol.h"

namespace rosin::discovery
{

TrialSimulator::TrialSimulator(const SimulationModel& model, double sampleRate)
    : sampleRate_(sampleRate), period_(1.0 / model.preset.string.fundamental())
{
    voice_.prepare(voiceConfig(model), frictionLaw(model), sampleRate);
}

const std::vector<physics::VoiceSample>& TrialSimulator::run(const TrialSettings& settings)
{
    // The scan's protocol: a spec holding only what TrialProtocol reads, and the trial as its one cell.
    scan::ScanSpec spec;
    spec.sampleRate = sampleRate_;
    spec.trialSeconds = settings.seconds;
    spec.rampSeconds = 0.0;
    scan::CellSettings cell{0, settings.beta, settings.bowForce, 0.0};
    if (const auto* a = std::get_if<ConstantAcceleration>(&settings.gesture))
    {
        spec.kind = scan::ScanKind::Guettler;
        cell.second = a->acceleration;
    }
    else if (const auto* s = std::get_if<Steady>(&settings.gesture))
    {
        spec.kind = scan::ScanKind::Schelleng;
        cell.second = s->speed;
    }
    else
    {
        throw std::invalid_argument("TrialSimulator: a recorded gesture is not simulated");
    }
    const scan::TrialProtocol protocol(spec, cell);
    voice_.reset();
    samples_.clear();
    samples_.reserve(protocol.samples());
    for (std::size_t k = 0; k < protocol.samples(); ++k)
        samples_.push_back(voice_.step(protocol.at(k)));
    return samples_;
}

std::vector<double> channelSamples(const std::vector<physics::VoiceSample>& samples, const std::string& name)
{
    double physics::VoiceSample::*member = nullptr;
    if (name == "bridgeForce")
        member = &physics::VoiceSample::bridgeForce;
    else if (name == "frictionForce")
        member = &physics::VoiceSample::frictionForce;
    else if (name == "bowPointVelocity")
        member = &physics::VoiceSample::bowPointVelocity;
    else if (name == "bowVelocity")
        member = &physics::VoiceSample::bowVelocity;
    else
        throw std::invalid_argument("channelSamples: the simulation has no channel \"" + name + "\"");
    std::vector<double> values;
    values.reserve(samples.size());
    for (const auto& s : samples)
        values.push_back(s.*member);
    return values;
}

} // namespace rosin::discovery
