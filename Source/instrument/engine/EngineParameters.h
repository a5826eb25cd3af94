#pragma once
// The instrument's parameters as a host sees them: stable, versioned IDs (juce::ParameterID{id, 1}; a changed
// meaning gets a new version, never a reused ID), physical units and ranges, one table for everything that
// needs them (the plugin's parameter layout, the offline render's ParameterSet, automation files), and the
// plain snapshot of their values that a block plays with.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <juce_audio_processors/juce_audio_processors.h>

#include "core/physics/laws/FrictionLawFactory.h"
#include "instrument/engine/OutputStage.h"
#include "instrument/player/GestureParameters.h"

namespace rosin::engine
{

namespace ids
{
inline constexpr const char* bowForce = "bowForce";                     ///< N, 0.05..5
inline constexpr const char* bowSpeed = "bowSpeed";                     ///< m/s, 0.01..1
inline constexpr const char* attackAcceleration = "attackAcceleration"; ///< m/s^2, 0.05..10
inline constexpr const char* beta = "beta";                             ///< 0.02..0.3
inline constexpr const char* friction = "friction";                     ///< choice: the six laws
inline constexpr const char* body = "body";                             ///< bool
inline constexpr const char* ambientTemperature = "ambientTemperature"; ///< deg C, 0..40
inline constexpr const char* outputLevel = "outputLevel";               ///< dB, -60..+12
inline constexpr const char* instrument = "instrument";                 ///< choice: cello, violin
inline constexpr const char* string = "string";                         ///< choice: auto, I..IV
inline constexpr const char* intonation = "intonation";                 ///< bool: the player's ear corrects
inline constexpr const char* output = "output";                         ///< choice: OutputStage.h
inline constexpr const char* dcBlocker = "dcBlocker";                   ///< bool: on force and velocity
inline constexpr const char* bypass = "bypass";                         ///< bool: the host's bypass (silence)
inline constexpr const char* quality = "quality";                       ///< choice: full, live (ModelQuality)
inline constexpr const char* mapping = "mapping";                       ///< choice: lab, musical
inline constexpr const char* dynamics = "dynamics";                     ///< pp 0 .. ff 1 (musical)
inline constexpr const char* bowPressure = "bowPressure";               ///< flautando 0 .. scratch 1
inline constexpr const char* vibratoDepth = "vibratoDepth";             ///< cents, 0..40
inline constexpr const char* vibratoRate = "vibratoRate";               ///< Hz, 3..9
inline constexpr const char* vibratoDelay = "vibratoDelay";             ///< s, 0..1.5
inline constexpr const char* slideTime = "slideTime";                   ///< s, the slowest slur, 0.02..0.5
inline constexpr const char* tremoloRate = "tremoloRate";               ///< bow changes per second, 4..20
inline constexpr const char* articulation = "articulation";             ///< choice: arco, pizzicato
inline constexpr int version = 1;
} // namespace ids

/// Each parameter's place in the table (allParameterIds(), RawParameterValues).
enum class ParameterIndex : int
{
    bowForce,
    bowSpeed,
    attackAcceleration,
    beta,
    friction,
    body,
    ambientTemperature,
    outputLevel,
    instrument,
    string,
    intonation,
    output,
    dcBlocker,
    bypass,
    quality,
    mapping,
    dynamics,
    bowPressure,
    vibratoDepth,
    vibratoRate,
    vibratoDelay,
    slideTime,
    tremoloRate,
    articulation
};
inline constexpr int kParameterCount = static_cast<int>(ParameterIndex::articulation) + 1;
/// Every parameter ID, in the table's order.
const std::array<const char*, kParameterCount>& allParameterIds();
/// Index of `id` in allParameterIds(), or -1.
int parameterIndex(const std::string& id) noexcept;

/// The calibration ambient of the thermal laws: ContactParameters::ambientOffset = T - 20 C.
inline constexpr double kCalibrationAmbientCelsius = 20.0;
/// Default output level: the demo phrase peaks near -6 dBFS (with the scale of OutputStage.h).
inline constexpr float kDefaultOutputLevelDb = -12.0f;

/// One parameter of the table: what the host shows and what an automation file may write.
struct ParameterSpec
{
    enum class Kind
    {
        Continuous, ///< a float in [min, max] in its own unit
        Choice,     ///< an index into `choices`
        Switch      ///< off (0) or on (1)
    };
    const char* id = "";
    const char* name = "";
    Kind kind = Kind::Continuous;
    double min = 0.0, max = 1.0;      ///< plain range (a choice: 0..n-1, a switch: 0..1)
    float defaultValue = 0.0f;        ///< plain
    float skewCentre = 0.0f;          ///< continuous: the value at mid-travel (0: linear)
    const char* unit = "";            ///< continuous: the label
    int decimals = 0;                 ///< continuous: digits shown
    std::vector<std::string> choices; ///< a choice's names, in index order
};

/// The table, in the order of allParameterIds().
const std::vector<ParameterSpec>& parameterSpecs();
/// The spec of `id`, or null.
const ParameterSpec* findParameterSpec(const std::string& id) noexcept;

/// One JUCE parameter object per spec, in the table's order: the plugin hands them to its
/// AudioProcessorValueTreeState, the offline render keeps them in a ParameterSet, so both quantise values
/// alike.
std::vector<std::unique_ptr<juce::RangedAudioParameter>> makeParameters();

/// Sets `parameter` to the plain value `plain` as a user's move does (setValueNotifyingHost of its normalised
/// value). With `onlyIfChanged`, nothing happens when the normalised value is already that; returns whether
/// it was set.
bool setPlainValue(juce::RangedAudioParameter& parameter, float plain, bool onlyIfChanged = false);

/// How much of the model runs: the full model, or the live quality, whose strings and body stop at
/// kLiveBandwidthHz (Resources/docs/benchmarks.md, "Quality", gives its cost and what it changes in the
/// sound).
enum class ModelQuality : int
{
    Full,
    Live
};
inline constexpr double kLiveBandwidthHz = 10000.0;

/// What the instrument is built from: changing any of these rebuilds it off the audio thread.
struct InstrumentKey
{
    int instrument = 0; ///< 0 cello, 1 violin
    physics::FrictionModel friction = physics::FrictionModel::Plastic;
    bool body = true;
    double ambientCelsius = 20.0;
    ModelQuality quality = ModelQuality::Full;
    bool operator==(const InstrumentKey&) const = default;
};

/// Plain values in SI units, read once per block.
struct ParameterSnapshot
{
    player::GestureParameters gesture;
    InstrumentKey key;
    OutputSettings output;
    int stringChoice = 0; ///< 0 auto, 1..4 = string I (highest) .. IV
    bool intonationByEar = true;
};

/// The raw (denormalised) values a host holds, in the table's order.
struct RawParameterValues
{
    std::array<float, kParameterCount> values{};
    float operator[](ParameterIndex i) const noexcept { return values[static_cast<std::size_t>(i)]; }
    float& operator[](ParameterIndex i) noexcept { return values[static_cast<std::size_t>(i)]; }
};

/// The instrument key of raw values; a non-finite value reads as its default.
InstrumentKey instrumentKeyOf(const RawParameterValues& raw) noexcept;
/// The block's snapshot of raw values; stringCount maps the string choice to a string index.
ParameterSnapshot snapshotOf(const RawParameterValues& raw, int stringCount) noexcept;

} // namespace rosin::engine
