#include "PluginParameters.h"

#include <cmath>

namespace rosin::plugin
{

const std::array<const char*, 14>& allParameterIds()
{
    static const std::array<const char*, 14> list = {
        ids::bowForce,   ids::bowSpeed, ids::attackAcceleration, ids::beta,
        ids::friction,   ids::body,     ids::ambientTemperature, ids::outputLevel,
        ids::instrument, ids::string,   ids::intonation,         ids::output,
        ids::dcBlocker,  ids::bypass};
    return list;
}

namespace
{
// Log-like taper centred where players spend their time, in the parameter's own unit.
juce::NormalisableRange<float> physicalRange(const gesture::Range& r, float centre)
{
    juce::NormalisableRange<float> range(static_cast<float>(r.min), static_cast<float>(r.max));
    range.setSkewForCentre(centre);
    return range;
}

juce::AudioParameterFloatAttributes unit(const char* label, int decimals)
{
    return juce::AudioParameterFloatAttributes().withLabel(label).withStringFromValueFunction(
        [decimals](float v, int) { return juce::String(v, decimals); });
}

juce::ParameterID pid(const char* id)
{
    return juce::ParameterID{id, ids::version};
}

juce::StringArray frictionChoices()
{
    juce::StringArray names;
    for (const auto& n : physics::frictionModelNames())
        names.add(n);
    return names;
}
} // namespace

namespace defaults
{
constexpr float bowForce = 1.0f, bowSpeed = 0.1f, attackAcceleration = 2.0f, beta = 0.0899f;
constexpr float ambientCelsius = 20.0f;
} // namespace defaults

/// A raw parameter value, or `fallback` when it is not finite: a host or a damaged project can deliver NaN,
/// and one NaN in a smoother would silence the engine for good.
float finiteOr(const std::atomic<float>* value, float fallback) noexcept
{
    const float x = value->load();
    return std::isfinite(x) ? x : fallback;
}

juce::AudioProcessorValueTreeState::ParameterLayout createParameterLayout()
{
    namespace r = gesture::ranges;
    juce::AudioProcessorValueTreeState::ParameterLayout layout;
    layout.add(std::make_unique<juce::AudioParameterFloat>(
        pid(ids::bowForce), "Bow force", physicalRange(r::bowForce, 1.0f), defaults::bowForce, unit("N", 3)));
    layout.add(std::make_unique<juce::AudioParameterFloat>(pid(ids::bowSpeed), "Bow speed",
                                                           physicalRange(r::bowSpeed, 0.1f),
                                                           defaults::bowSpeed, unit("m/s", 3)));
    layout.add(std::make_unique<juce::AudioParameterFloat>(
        pid(ids::attackAcceleration), "Attack acceleration", physicalRange(r::attackAcceleration, 1.0f),
        defaults::attackAcceleration, unit("m/s^2", 2)));
    layout.add(std::make_unique<juce::AudioParameterFloat>(
        pid(ids::beta), "Bow position (beta)", physicalRange(r::beta, 0.1f), defaults::beta, unit("", 4)));
    layout.add(
        std::make_unique<juce::AudioParameterChoice>(pid(ids::friction), "Friction law", frictionChoices(),
                                                     static_cast<int>(physics::FrictionModel::Plastic)));
    layout.add(std::make_unique<juce::AudioParameterBool>(pid(ids::body), "Body", true));
    layout.add(std::make_unique<juce::AudioParameterFloat>(
        pid(ids::ambientTemperature), "Ambient temperature", juce::NormalisableRange<float>(0.0f, 40.0f),
        defaults::ambientCelsius, unit("C", 1)));
    layout.add(std::make_unique<juce::AudioParameterFloat>(pid(ids::outputLevel), "Output level",
                                                           juce::NormalisableRange<float>(-60.0f, 12.0f),
                                                           kDefaultOutputLevelDb, unit("dB", 1)));
    layout.add(std::make_unique<juce::AudioParameterChoice>(pid(ids::instrument), "Instrument",
                                                            juce::StringArray{"cello", "violin"}, 0));
    layout.add(std::make_unique<juce::AudioParameterChoice>(
        pid(ids::string), "String", juce::StringArray{"auto", "I", "II", "III", "IV"}, 0));
    layout.add(std::make_unique<juce::AudioParameterBool>(pid(ids::intonation), "Intonation by ear", true));
    layout.add(std::make_unique<juce::AudioParameterChoice>(pid(ids::output), "Output", outputChoiceNames(),
                                                            static_cast<int>(OutputChoice::RadiatedSound)));
    layout.add(std::make_unique<juce::AudioParameterBool>(pid(ids::dcBlocker), "DC blocker", true));
    // The plugin's own bypass (getBypassParameter): hosts show it as theirs, and JUCE's VST3 wrapper then
    // never parses the private trailer of a saved state (a damaged trailer crashed it, issue 19).
    layout.add(std::make_unique<juce::AudioParameterBool>(pid(ids::bypass), "Bypass", false));
    return layout;
}

ParameterReader::ParameterReader(juce::AudioProcessorValueTreeState& state)
    : bowForce_(state.getRawParameterValue(ids::bowForce)),
      bowSpeed_(state.getRawParameterValue(ids::bowSpeed)),
      attackAcceleration_(state.getRawParameterValue(ids::attackAcceleration)),
      beta_(state.getRawParameterValue(ids::beta)), friction_(state.getRawParameterValue(ids::friction)),
      body_(state.getRawParameterValue(ids::body)),
      ambientTemperature_(state.getRawParameterValue(ids::ambientTemperature)),
      outputLevel_(state.getRawParameterValue(ids::outputLevel)),
      instrument_(state.getRawParameterValue(ids::instrument)),
      string_(state.getRawParameterValue(ids::string)),
      intonation_(state.getRawParameterValue(ids::intonation)),
      output_(state.getRawParameterValue(ids::output)), dcBlocker_(state.getRawParameterValue(ids::dcBlocker))
{
    jassert(bowForce_ && bowSpeed_ && attackAcceleration_ && beta_ && friction_ && body_ &&
            ambientTemperature_ && outputLevel_ && instrument_ && string_ && intonation_ && output_ &&
            dcBlocker_);
}

InstrumentKey ParameterReader::readKey() const noexcept
{
    InstrumentKey key;
    key.instrument = juce::jlimit(0, 1, static_cast<int>(std::lround(finiteOr(instrument_, 0.0f))));
    key.friction = static_cast<physics::FrictionModel>(
        juce::jlimit(0, 5,
                     static_cast<int>(std::lround(
                         finiteOr(friction_, static_cast<float>(physics::FrictionModel::Plastic))))));
    key.body = body_->load() >= 0.5f;
    key.ambientCelsius = finiteOr(ambientTemperature_, defaults::ambientCelsius);
    return key;
}

ParameterSnapshot ParameterReader::read(int stringCount) const noexcept
{
    ParameterSnapshot s;
    s.gesture.bowForce = finiteOr(bowForce_, defaults::bowForce);
    s.gesture.bowSpeed = finiteOr(bowSpeed_, defaults::bowSpeed);
    s.gesture.attackAcceleration = finiteOr(attackAcceleration_, defaults::attackAcceleration);
    s.gesture.beta = finiteOr(beta_, defaults::beta);
    s.stringChoice = juce::jlimit(0, 4, static_cast<int>(std::lround(finiteOr(string_, 0.0f))));
    // String I is the highest, as string players number them; the controller counts from the lowest.
    s.gesture.stringOverride = s.stringChoice == 0 ? -1 : juce::jmax(0, stringCount - s.stringChoice);
    s.key = readKey();
    s.intonationByEar = intonation_->load() >= 0.5f;
    s.output.gain = std::pow(10.0, finiteOr(outputLevel_, kDefaultOutputLevelDb) / 20.0);
    s.output.choice =
        static_cast<OutputChoice>(juce::jlimit(0, 2, static_cast<int>(std::lround(finiteOr(output_, 0.0f)))));
    s.output.dcBlocker = dcBlocker_->load() >= 0.5f;
    return s;
}

} // namespace rosin::plugin
