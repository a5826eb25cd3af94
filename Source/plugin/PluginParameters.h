#pragma once
// The plugin's host parameters: stable, versioned IDs (juce::ParameterID{id, 1}; a changed meaning gets a new
// version, never a reused ID), physical units, and the once-per-block snapshot the audio thread reads.
#include <array>

#include <juce_audio_processors/juce_audio_processors.h>

#include "OutputStage.h"
#include "gesture/GestureParameters.h"
#include "physics/laws/FrictionLawFactory.h"

namespace rosin::plugin
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
inline constexpr int version = 1;
} // namespace ids

/// Every parameter ID, for tests and fuzzers.
const std::array<const char*, 14>& allParameterIds();

/// The calibration ambient of the thermal laws: ContactParameters::ambientOffset = T - 20 C.
inline constexpr double kCalibrationAmbientCelsius = 20.0;
/// Default output level: the demo phrase peaks near -6 dBFS (with the scale of OutputStage.h).
inline constexpr float kDefaultOutputLevelDb = -12.0f;

juce::AudioProcessorValueTreeState::ParameterLayout createParameterLayout();

/// What the instrument is built from: changing any of these rebuilds it off the audio thread.
struct InstrumentKey
{
    int instrument = 0; ///< 0 cello, 1 violin
    physics::FrictionModel friction = physics::FrictionModel::Plastic;
    bool body = true;
    double ambientCelsius = 20.0;
    bool operator==(const InstrumentKey&) const = default;
};

/// Plain values in SI units, read once per block.
struct ParameterSnapshot
{
    gesture::GestureParameters gesture;
    InstrumentKey key;
    OutputSettings output;
    int stringChoice = 0; ///< 0 auto, 1..4 = string I (highest) .. IV
    bool intonationByEar = true;
};

/// Direct pointers to the parameters' atomics: the audio thread never looks a parameter up by string.
class ParameterReader
{
  public:
    explicit ParameterReader(juce::AudioProcessorValueTreeState& state);
    /// Audio thread safe: atomic loads only. stringCount maps the string choice to a string index.
    ParameterSnapshot read(int stringCount) const noexcept;
    InstrumentKey readKey() const noexcept;

  private:
    std::atomic<float>* bowForce_;
    std::atomic<float>* bowSpeed_;
    std::atomic<float>* attackAcceleration_;
    std::atomic<float>* beta_;
    std::atomic<float>* friction_;
    std::atomic<float>* body_;
    std::atomic<float>* ambientTemperature_;
    std::atomic<float>* outputLevel_;
    std::atomic<float>* instrument_;
    std::atomic<float>* string_;
    std::atomic<float>* intonation_;
    std::atomic<float>* output_;
    std::atomic<float>* dcBlocker_;
};

} // namespace rosin::plugin
