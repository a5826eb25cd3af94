#include "OutputStage.h"

#include <cmath>

#include "SoftClip.h"

namespace rosin::plugin
{

juce::StringArray outputChoiceNames()
{
    return {"radiated sound", "bridge force", "bridge velocity"};
}

std::optional<OutputChoice> outputChoiceFromName(const juce::String& name)
{
    const int index = outputChoiceNames().indexOf(name);
    if (index < 0)
        return std::nullopt;
    return static_cast<OutputChoice>(index);
}

void OutputStage::prepare(double sampleRate, double gainSmoothingSeconds)
{
    dcBlocker_.coefficients =
        juce::dsp::IIR::Coefficients<double>::makeFirstOrderHighPass(sampleRate, kDcBlockerHz);
    gain_.prepare(gainSmoothingSeconds, sampleRate);
    reset();
}

void OutputStage::reset() noexcept
{
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

float OutputStage::process(const physics::BowedInstrument& instrument, double bridgeForce,
                           const OutputSettings& settings, bool& nonFinite) noexcept
{
    double y = quantity(instrument, bridgeForce, settings.choice);
    nonFinite = !std::isfinite(y);
    if (nonFinite)
        y = 0.0;
    // The blocker runs on every sample so that switching it on mid-note starts from a settled state.
    const double blocked = dcBlocker_.processSample(y);
    if (settings.dcBlocker && settings.choice != OutputChoice::RadiatedSound)
        y = blocked;
    return static_cast<float>(softClip(y * gain_.process(settings.gain)));
}

} // namespace rosin::plugin
