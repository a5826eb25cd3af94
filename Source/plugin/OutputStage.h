#pragma once
// What the plugin sends to the host, one sample at a time: the quantity the user chose (the sound the body
// radiates by default; the bridge force or the bridge velocity for the lab), scaled to audio, DC-blocked
// where the quantity has a DC (the bow's static pull on the bridge), guarded against non-finite values and
// soft-clipped. Real-time safe after prepare().
#include <juce_dsp/juce_dsp.h>

#include "gesture/OnePoleSmoother.h"
#include "physics/instrument/BowedInstrument.h"

namespace rosin::plugin
{

enum class OutputChoice
{
    RadiatedSound = 0,
    BridgeForce = 1,
    BridgeVelocity = 2
};

/// Host-visible names, in choice order: "radiated sound", "bridge force", "bridge velocity".
juce::StringArray outputChoiceNames();
/// By name (as above); std::nullopt for anything else.
std::optional<OutputChoice> outputChoiceFromName(const juce::String& name);

/// Audio sample per unit of each quantity at 0 dB output level. Calibrations, not physics: fixed so that the
/// demo phrase at the default output level (-12 dB) peaks near -6 dBFS with each output.
inline constexpr double kAudioPerPascal = 1.0;
inline constexpr double kAudioPerNewton = 1.0;
inline constexpr double kAudioPerMetrePerSecond = 1.0;
/// Corner of the DC blocker on the bridge force and velocity outputs: 0.1 dB down at the cello's C2.
inline constexpr double kDcBlockerHz = 10.0;

struct OutputSettings
{
    OutputChoice choice = OutputChoice::RadiatedSound;
    bool dcBlocker = true; ///< force and velocity only: the radiated sound has no DC by physics
    double gain = 1.0;     ///< linear, the output level
};

class OutputStage
{
  public:
    /// Off the audio thread.
    void prepare(double sampleRate, double gainSmoothingSeconds);
    void reset() noexcept;
    /// The sample for this step of `instrument`, whose step returned `bridgeForce`. `nonFinite` is set when
    /// the quantity was not finite (the sample is then 0).
    float process(const physics::BowedInstrument& instrument, double bridgeForce,
                  const OutputSettings& settings, bool& nonFinite) noexcept;

  private:
    juce::dsp::IIR::Filter<double> dcBlocker_;
    gesture::OnePoleSmoother gain_;
};

} // namespace rosin::plugin
