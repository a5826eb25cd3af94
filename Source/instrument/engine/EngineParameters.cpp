#include "instrument/engine/EngineParameters.h"

#include <algorithm>
#include <cmath>

namespace rosin::engine
{

const std::array<const char*, kParameterCount>& allParameterIds()
{
    static const std::array<const char*, kParameterCount> list = {ids::bowForce,
                                                                  ids::bowSpeed,
                                                                  ids::attackAcceleration,
                                                                  ids::beta,
                                                                  ids::friction,
                                                                  ids::body,
                                                                  ids::ambientTemperature,
                                                                  ids::outputLevel,
                                                                  ids::instrument,
                                                                  ids::string,
                                                                  ids::intonation,
                                                                  ids::output,
                                                                  ids::dcBlocker,
                                                                  ids::bypass,
                                                                  ids::quality,
                                                                  ids::mapping,
                                                                  ids::dynamics,
                                                                  ids::bowPressure,
                                                                  ids::vibratoDepth,
                                                                  ids::vibratoRate,
                                                                  ids::vibratoDelay,
                                                                  ids::slideTime,
                                                                  ids::tremoloRate,
                                                                  ids::articulation};
    return list;
}

int parameterIndex(const std::string& id) noexcept
{
    const auto& list = allParameterIds();
    for (int i = 0; i < kParameterCount; ++i)
        if (id == list[static_cast<std::size_t>(i)])
            return i;
    return -1;
}

namespace
{
// The player's defaults are the parameters' defaults: said once, in player::GestureParameters.
namespace defaults
{
constexpr player::GestureParameters playerDefaults{};
constexpr float bowForce = static_cast<float>(playerDefaults.bowForce),
                bowSpeed = static_cast<float>(playerDefaults.bowSpeed),
                attackAcceleration = static_cast<float>(playerDefaults.attackAcceleration),
                beta = static_cast<float>(playerDefaults.beta);
constexpr float dynamics = static_cast<float>(playerDefaults.dynamics),
                bowPressure = static_cast<float>(playerDefaults.bowPressure),
                vibratoDepth = static_cast<float>(playerDefaults.vibratoDepth),
                vibratoRate = static_cast<float>(playerDefaults.vibratoRate),
                vibratoDelay = static_cast<float>(playerDefaults.vibratoDelay),
                slideTime = static_cast<float>(playerDefaults.slideTime),
                tremoloRate = static_cast<float>(playerDefaults.tremoloRate);
constexpr float ambientCelsius = 20.0f;
} // namespace defaults

using Kind = ParameterSpec::Kind;
using P = ParameterIndex;

// A physical quantity with a log-like taper centred where players spend their time.
ParameterSpec physical(const char* id, const char* name, const physics::Range& r, float defaultValue,
                       float centre, int decimals)
{
    return {id, name, Kind::Continuous, r.min, r.max, defaultValue, centre, r.unit, decimals, {}};
}

ParameterSpec choice(const char* id, const char* name, std::vector<std::string> names, int defaultIndex)
{
    const double last = static_cast<double>(names.size()) - 1.0;
    return {id, name, Kind::Choice,    0.0, last, static_cast<float>(defaultIndex), 0.0f,
            "", 0,    std::move(names)};
}

ParameterSpec onOff(const char* id, const char* name, bool on)
{
    return {id, name, Kind::Switch, 0.0, 1.0, on ? 1.0f : 0.0f, 0.0f, "", 0, {}};
}

std::vector<std::string> outputNames()
{
    std::vector<std::string> names;
    for (const auto& n : outputChoiceNames())
        names.push_back(n.toStdString());
    return names;
}

std::vector<ParameterSpec> buildSpecs()
{
    namespace r = player::ranges;
    std::vector<ParameterSpec> s;
    s.push_back(physical(ids::bowForce, "Bow force", r::bowForce, defaults::bowForce, 1.0f, 3));
    s.push_back(physical(ids::bowSpeed, "Bow speed", r::bowSpeed, defaults::bowSpeed, 0.1f, 3));
    s.push_back(physical(ids::attackAcceleration, "Attack acceleration", r::attackAcceleration,
                         defaults::attackAcceleration, 1.0f, 2));
    s.push_back(physical(ids::beta, "Bow position (beta)", r::beta, defaults::beta, 0.1f, 4));
    s.push_back(choice(ids::friction, "Friction law", physics::frictionModelNames(),
                       static_cast<int>(physics::FrictionModel::Plastic)));
    s.push_back(onOff(ids::body, "Body", true));
    s.push_back({ids::ambientTemperature,
                 "Ambient temperature",
                 Kind::Continuous,
                 0.0,
                 40.0,
                 defaults::ambientCelsius,
                 0.0f,
                 "C",
                 1,
                 {}});
    s.push_back({ids::outputLevel,
                 "Output level",
                 Kind::Continuous,
                 -60.0,
                 12.0,
                 kDefaultOutputLevelDb,
                 0.0f,
                 "dB",
                 1,
                 {}});
    s.push_back(choice(ids::instrument, "Instrument", {"cello", "violin"}, 0));
    s.push_back(choice(ids::string, "String", {"auto", "I", "II", "III", "IV"}, 0));
    s.push_back(onOff(ids::intonation, "Intonation by ear", true));
    s.push_back(choice(ids::output, "Output", outputNames(), static_cast<int>(OutputChoice::RadiatedSound)));
    s.push_back(onOff(ids::dcBlocker, "DC blocker", true));
    // The plugin's own bypass (getBypassParameter): hosts show it as theirs, and JUCE's VST3 wrapper then
    // never parses the private trailer of a saved state (a damaged trailer crashed it).
    s.push_back(onOff(ids::bypass, "Bypass", false));
    // Appended, not inserted: the table's order is the automation files' and the saved states' order.
    s.push_back(choice(ids::quality, "Quality", {"full", "live"}, static_cast<int>(ModelQuality::Full)));
    // The musical mapping's (player::GestureParameters). Its default is the lab's, which projects saved
    // before it existed played with; the musical programs set it.
    s.push_back(choice(ids::mapping, "Mapping", {"lab", "musical"}, static_cast<int>(player::Mapping::Lab)));
    s.push_back(physical(ids::dynamics, "Dynamics", r::dynamics, defaults::dynamics, 0.0f, 2));
    s.push_back(physical(ids::bowPressure, "Bow pressure", r::bowPressure, defaults::bowPressure, 0.0f, 2));
    s.push_back(
        physical(ids::vibratoDepth, "Vibrato depth", r::vibratoDepth, defaults::vibratoDepth, 0.0f, 1));
    s.push_back(physical(ids::vibratoRate, "Vibrato rate", r::vibratoRate, defaults::vibratoRate, 0.0f, 2));
    s.push_back(
        physical(ids::vibratoDelay, "Vibrato delay", r::vibratoDelay, defaults::vibratoDelay, 0.0f, 2));
    s.push_back(physical(ids::slideTime, "Slide time", r::slideTime, defaults::slideTime, 0.0f, 3));
    s.push_back(physical(ids::tremoloRate, "Tremolo rate", r::tremoloRate, defaults::tremoloRate, 0.0f, 1));
    s.push_back(choice(ids::articulation, "Articulation", {"arco", "pizzicato"},
                       static_cast<int>(player::Articulation::Arco)));
    return s;
}

std::unique_ptr<juce::RangedAudioParameter> makeParameter(const ParameterSpec& spec)
{
    const juce::ParameterID pid{spec.id, ids::version};
    switch (spec.kind)
    {
    case Kind::Continuous:
    {
        juce::NormalisableRange<float> range(static_cast<float>(spec.min), static_cast<float>(spec.max));
        if (spec.skewCentre > 0.0f)
            range.setSkewForCentre(spec.skewCentre);
        const int decimals = spec.decimals;
        return std::make_unique<juce::AudioParameterFloat>(
            pid, spec.name, range, spec.defaultValue,
            juce::AudioParameterFloatAttributes().withLabel(spec.unit).withStringFromValueFunction(
                [decimals](float v, int) { return juce::String(v, decimals); }));
    }
    case Kind::Choice:
    {
        juce::StringArray names;
        for (const auto& n : spec.choices)
            names.add(n);
        return std::make_unique<juce::AudioParameterChoice>(pid, spec.name, names,
                                                            static_cast<int>(spec.defaultValue));
    }
    case Kind::Switch:
        break;
    }
    return std::make_unique<juce::AudioParameterBool>(pid, spec.name, spec.defaultValue >= 0.5f);
}

/// A raw value, or `fallback` when it is not finite: a host or a damaged project can deliver NaN, and one
/// NaN in a smoother would silence the engine for good.
float finiteOr(float x, float fallback) noexcept
{
    return std::isfinite(x) ? x : fallback;
}
} // namespace

const std::vector<ParameterSpec>& parameterSpecs()
{
    static const std::vector<ParameterSpec> specs = buildSpecs();
    return specs;
}

const ParameterSpec* findParameterSpec(const std::string& id) noexcept
{
    const int i = parameterIndex(id);
    return i < 0 ? nullptr : &parameterSpecs()[static_cast<std::size_t>(i)];
}

std::vector<std::unique_ptr<juce::RangedAudioParameter>> makeParameters()
{
    std::vector<std::unique_ptr<juce::RangedAudioParameter>> parameters;
    for (const ParameterSpec& spec : parameterSpecs())
        parameters.push_back(makeParameter(spec));
    return parameters;
}

bool setPlainValue(juce::RangedAudioParameter& parameter, float plain, bool onlyIfChanged)
{
    const float normalised = parameter.convertTo0to1(plain);
    if (onlyIfChanged && normalised == parameter.getValue())
        return false;
    parameter.setValueNotifyingHost(normalised);
    return true;
}

InstrumentKey instrumentKeyOf(const RawParameterValues& raw) noexcept
{
    InstrumentKey key;
    key.instrument = std::clamp(static_cast<int>(std::lround(finiteOr(raw[P::instrument], 0.0f))), 0, 1);
    key.friction = static_cast<physics::FrictionModel>(
        std::clamp(static_cast<int>(std::lround(
                       finiteOr(raw[P::friction], static_cast<float>(physics::FrictionModel::Plastic)))),
                   0, physics::kFrictionModelCount - 1));
    key.body = raw[P::body] >= 0.5f;
    key.ambientCelsius = finiteOr(raw[P::ambientTemperature], defaults::ambientCelsius);
    key.quality = raw[P::quality] >= 0.5f ? ModelQuality::Live : ModelQuality::Full;
    return key;
}

ParameterSnapshot snapshotOf(const RawParameterValues& raw, int stringCount) noexcept
{
    ParameterSnapshot s;
    s.gesture.bowForce = finiteOr(raw[P::bowForce], defaults::bowForce);
    s.gesture.bowSpeed = finiteOr(raw[P::bowSpeed], defaults::bowSpeed);
    s.gesture.attackAcceleration = finiteOr(raw[P::attackAcceleration], defaults::attackAcceleration);
    s.gesture.beta = finiteOr(raw[P::beta], defaults::beta);
    s.gesture.mapping = raw[P::mapping] >= 0.5f ? player::Mapping::Musical : player::Mapping::Lab;
    s.gesture.dynamics = finiteOr(raw[P::dynamics], defaults::dynamics);
    s.gesture.bowPressure = finiteOr(raw[P::bowPressure], defaults::bowPressure);
    s.gesture.vibratoDepth = finiteOr(raw[P::vibratoDepth], defaults::vibratoDepth);
    s.gesture.vibratoRate = finiteOr(raw[P::vibratoRate], defaults::vibratoRate);
    s.gesture.vibratoDelay = finiteOr(raw[P::vibratoDelay], defaults::vibratoDelay);
    s.gesture.slideTime = finiteOr(raw[P::slideTime], defaults::slideTime);
    s.gesture.tremoloRate = finiteOr(raw[P::tremoloRate], defaults::tremoloRate);
    s.gesture.articulation =
        raw[P::articulation] >= 0.5f ? player::Articulation::Pizzicato : player::Articulation::Arco;
    s.stringChoice = std::clamp(static_cast<int>(std::lround(finiteOr(raw[P::string], 0.0f))), 0, 4);
    // String I is the highest, as string players number them; the controller counts from the lowest.
    s.gesture.stringOverride = s.stringChoice == 0 ? -1 : std::max(0, stringCount - s.stringChoice);
    s.key = instrumentKeyOf(raw);
    s.intonationByEar = raw[P::intonation] >= 0.5f;
    s.output.gain = std::pow(10.0, finiteOr(raw[P::outputLevel], kDefaultOutputLevelDb) / 20.0);
    s.output.choice = static_cast<OutputChoice>(
        std::clamp(static_cast<int>(std::lround(finiteOr(raw[P::output], 0.0f))), 0, 2));
    s.output.dcBlocker = raw[P::dcBlocker] >= 0.5f;
    return s;
}

} // namespace rosin::engine
