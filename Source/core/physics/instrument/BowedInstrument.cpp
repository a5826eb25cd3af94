#include "core/physics/instrument/BowedInstrument.h"

#include <algorithm>
#include <numbers>

namespace rosin::physics
{

InstrumentConfig celloInstrument()
{
    InstrumentConfig c;
    c.name = "cello";
    for (const char* s : {"cello-C2", "cello-G2", "cello-D3", "cello-A3"})
        c.strings.push_back(stringFromCatalogue(s));
    c.body = celloBody();
    c.soundBody = c.body;
    return c;
}

InstrumentConfig violinInstrument()
{
    InstrumentConfig c;
    c.name = "violin";
    for (const char* s : {"violin-G3", "violin-D4", "violin-A4", "violin-E5-instrument"})
        c.strings.push_back(stringFromCatalogue(s));
    c.body = violinBody();
    c.soundBody = c.body;
    c.contact = schumacherContact();
    return c;
}

void BowedInstrument::prepare(const InstrumentConfig& config, double sampleRate)
{
    config_ = config;
    voices_.clear();
    VoiceConfig reference;
    const double bandRatio = config.modeBandwidthHz > 0.0 ? std::min(reference.maxModeFrequencyRatio,
                                                                     config.modeBandwidthHz / sampleRate)
                                                          : reference.maxModeFrequencyRatio;
    const double modeLimit = 2.0 * std::numbers::pi * bandRatio * sampleRate;
    body_.configure(config.body, sampleRate, modeLimit);
    listeningBody_.configure(config.body.rigid() ? config.soundBody : BodyParameters{}, sampleRate,
                             modeLimit);
    for (const auto& s : config.strings)
    {
        VoiceConfig vc;
        vc.string = s; // vc.body stays rigid: the strings share body_
        vc.torsion = config.torsion;
        vc.bendingStiffness = config.bendingStiffness;
        vc.bow = config.bow;
        vc.maxModeFrequencyRatio = bandRatio;
        auto voice = std::make_unique<BowedStringVoice>();
        voice->prepare(vc, makeFrictionLaw(config.friction, config.contact), sampleRate);
        voice->useSharedBody(&body_);
        voices_.push_back(std::move(voice));
    }
}

void BowedInstrument::reset() noexcept
{
    for (auto& v : voices_)
        v->reset();
    body_.reset();
    listeningBody_.reset();
    lastTotal_ = 0.0;
    recovered_ = false;
}

double BowedInstrument::step(const BowInput* inputs, VoiceSample* outputs) noexcept
{
    // Each junction predicts the other strings' bridge force from the last sample; then the total bridge
    // force G follows exactly from sum_i F_i = sum_i (R_i - c_i G), and every string and the body are driven
    // with it, so the linear system (strings + body) stays the exact discretised Lagrangian one.
    double sumR = 0.0, sumC = 0.0;
    for (std::size_t i = 0; i < voices_.size(); ++i)
    {
        const double others = lastTotal_ - voices_[i]->lastBridgeForce();
        sumR += voices_[i]->solveJunction(inputs[i], others);
        sumC += voices_[i]->bridgeCoupling();
    }
    const double G = sumR / (1.0 + sumC);
    double total = 0.0;
    recovered_ = false;
    for (std::size_t i = 0; i < voices_.size(); ++i)
    {
        outputs[i] = voices_[i]->finishStep(G);
        recovered_ = recovered_ || voices_[i]->recoveredFromRunaway();
        total += voices_[i]->lastBridgeForce();
    }
    if (recovered_)
    {
        body_.reset(); // a string blew up and reset: start the bridge afresh too
        listeningBody_.reset();
    }
    else
    {
        body_.advance(G);
        listeningBody_.advance(G);
    }
    lastTotal_ = recovered_ ? 0.0 : G;
    return total;
}

double BowedInstrument::storedEnergy() const noexcept
{
    double e = body_.energyAtLastStep();
    for (const auto& v : voices_)
        e += v->storedEnergy();
    return e;
}

double BowedInstrument::openFrequency(int i) const noexcept
{
    return config_.strings[static_cast<std::size_t>(i)].fundamental();
}

} // namespace rosin::physics
