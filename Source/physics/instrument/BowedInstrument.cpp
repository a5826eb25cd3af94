#include "BowedInstrument.h"

namespace rosin::physics
{

InstrumentConfig celloInstrument()
{
    InstrumentConfig c;
    c.name = "cello";
    for (const char* s : {"cello-C2", "cello-G2", "cello-D3", "cello-A3"})
        c.strings.push_back(stringFromCatalogue(s));
    c.body = celloBody();
    return c;
}

InstrumentConfig violinInstrument()
{
    InstrumentConfig c;
    c.name = "violin";
    for (const char* s : {"violin-G3", "violin-D4", "violin-A4", "violin-E5-instrument"})
        c.strings.push_back(stringFromCatalogue(s));
    c.body = violinBody();
    c.contact = schumacherContact();
    return c;
}

void BowedInstrument::prepare(const InstrumentConfig& config, double sampleRate)
{
    config_ = config;
    voices_.clear();
    for (const auto& s : config.strings)
    {
        VoiceConfig vc;
        vc.string = s;
        vc.body = config.body;
        vc.torsion = config.torsion;
        vc.bendingStiffness = config.bendingStiffness;
        auto voice = std::make_unique<BowedStringVoice>();
        voice->prepare(vc, makeFrictionLaw(config.friction, config.contact), sampleRate);
        voices_.push_back(std::move(voice));
    }
}

void BowedInstrument::reset() noexcept
{
    for (auto& v : voices_)
        v->reset();
    recovered_ = false;
}

double BowedInstrument::step(const BowInput* inputs, VoiceSample* outputs) noexcept
{
    double total = 0.0;
    recovered_ = false;
    for (std::size_t i = 0; i < voices_.size(); ++i)
    {
        outputs[i] = voices_[i]->step(inputs[i]);
        recovered_ = recovered_ || voices_[i]->recoveredFromRunaway();
        total += outputs[i].bridgeForce;
    }
    return total;
}

double BowedInstrument::openFrequency(int i) const noexcept
{
    return config_.strings[static_cast<std::size_t>(i)].fundamental();
}

} // namespace rosin::physics
