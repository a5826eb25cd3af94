#include "instrument/engine/OutputStage.h"

#include <cmath>

#include "instrument/engine/SoftClip.h"

namespace rosin::engine
{

juce::StringArray outputChoiceNames()
{
    return {"radiated sound", "bridge force", "bridge velocity"};
}

void OutputStage::prepare(double sampleRate, double gainSmoothingSeconds, int maximumBlockSize)
{
    measured_.prepare(sampleRate, maximumBlockSize);
    dcBlocker_.coefficients =
        juce::dsp::IIR::Coefficients<double>::makeFirstOrderHighPass(sampleRate, kDcBlockerHz);
    gain_.prepare(gainSmoothingSeconds, sampleRate);
    reset();
}

void OutputStage::reset() noexcept
{
    measured_.reset();
    dcBlocker_.reset();
    gain_.reset();
}

namespace
{
double quantity(const physics::BowedInstrument& instrument, double bridgeForce, OutputChoice choice) noexcept
{
    switch (choice)
    {
    case OutputChoice::BridgeForce:
        return kAudioPerNewton * bridgeForce;
    case OutputChoice::BridgeVelocity:
        return kAudioPerMetrePerSecond * instrument.bridgeVelocity();
    case OutputChoice::RadiatedSound:
        break;
    }
    return kAudioPerPascal * instrument.radiatedPressure();
}
} // namespace

float OutputStage::sample(int i, const physics::BowedInstrument& instrument, double bridgeForce,
                          const OutputSettings& settings, bool& nonFinite) noexcept
{
    double y = quantity(instrument, bridgeForce, settings.choice);
    nonFinite = !std::isfinite(y) || !std::isfinite(bridgeForce);
    if (nonFinite)
        y = bridgeForce = 0.0;
    // The blocker runs on every sample so that switching it on mid-note starts from a settled state.
    const double blocked = dcBlocker_.processSample(y);
    if (settings.dcBlocker && settings.choice != OutputChoice::RadiatedSound)
        y = blocked;
    if (i < measured_.capacity())
        measured_.setForce(i, static_cast<float>(bridgeForce));
    return static_cast<float>(y);
}

void OutputStage::finishBlock(float* out, int n, const OutputSettings& settings) noexcept
{
    if (settings.choice == OutputChoice::RadiatedSound)
        measured_.mix(out, n, static_cast<float>(kAudioPerPascal));
    for (int i = 0; i < n; ++i)
        out[i] = static_cast<float>(softClip(out[i] * gain_.process(settings.gain)));
}

} // namespace rosin::engine
