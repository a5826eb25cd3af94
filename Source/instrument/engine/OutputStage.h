#pragma once
// What the instrument sends out (to the plugin's host, to a rendered file): the quantity the user chose (the
// sound the body radiates by default, from the modal body or from a measured body response; the bridge force
// or the bridge velocity for the lab), scaled to audio, DC-blocked where the quantity has a DC (the bow's
// static pull on the bridge), guarded against non-finite values, then per block gained and soft-clipped.
// Real-time safe after prepare().
#include <juce_dsp/juce_dsp.h>

#include "core/gesture/OnePoleSmoother.h"
#include "core/physics/instrument/BowedInstrument.h"
#include "instrument/engine/MeasuredRadiation.h"

namespace rosin::engine
{

enum class OutputChoice
{
    RadiatedSound = 0,
    BridgeForce = 1,
    BridgeVelocity = 2
};

/// Host-visible names, in choice order: "radiated sound", "bridge force", "bridge velocity".
juce::StringArray outputChoiceNames();

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
    void prepare(double sampleRate, double gainSmoothingSeconds, int maximumBlockSize);
    void reset() noexcept;
    /// Sample i of the block, before gain: this step of `instrument`, whose step returned `bridgeForce`.
    /// `nonFinite` is set when the quantity was not finite (the sample is then 0).
    float sample(int i, const physics::BowedInstrument& instrument, double bridgeForce,
                 const OutputSettings& settings, bool& nonFinite) noexcept;
    /// After the block's samples: the measured response's sound where one is in use, gain, soft clip.
    void finishBlock(float* out, int n, const OutputSettings& settings) noexcept;

    /// The measured body response (audio thread; MeasuredRadiation.h).
    MeasuredRadiation& measured() noexcept { return measured_; }
    int latencySamples() const noexcept { return measured_.latencySamples(); }

  private:
    MeasuredRadiation measured_;
    juce::dsp::IIR::Filter<double> dcBlocker_;
    gesture::OnePoleSmoother gain_;
};

} // namespace rosin::engine
