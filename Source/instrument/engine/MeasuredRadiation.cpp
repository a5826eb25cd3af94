#include "instrument/engine/MeasuredRadiation.h"

#include <algorithm>

namespace rosin::engine
{

void MeasuredRadiation::prepare(double sampleRate, int maximumBlockSize)
{
    const auto capacity = static_cast<std::size_t>(std::max(maximumBlockSize, 4096));
    force_.assign(capacity, 0.0f);
    wet_.assign(capacity, 0.0f);
    convolution_.prepare({sampleRate, static_cast<juce::uint32>(capacity), 1});
    fadeSamples_ = static_cast<int>(0.05 * sampleRate);
    engineCrossfadeSamples_ = static_cast<int>(0.06 * sampleRate); // JUCE's own transition lasts 50 ms
    prepared_ = true;
    // prepare() runs every queued load and builds its engine now: a response set before needs no wait.
    if (state_ == State::WaitingForEngine || state_ == State::EngineCrossfade || state_ == State::FadingIn)
        state_ = State::On;
}

void MeasuredRadiation::reset() noexcept
{
    convolution_.reset();
}

void MeasuredRadiation::use(juce::AudioBuffer<float>&& response, double sampleRate) noexcept
{
    const bool first = state_ == State::Off || state_ == State::FadingOut;
    convolution_.loadImpulseResponse(std::move(response), sampleRate, juce::dsp::Convolution::Stereo::no,
                                     juce::dsp::Convolution::Trim::no, juce::dsp::Convolution::Normalise::no);
    // A response that replaces one in use: JUCE crossfades between the two engines itself.
    if (first)
        state_ = State::WaitingForEngine;
}

void MeasuredRadiation::clear() noexcept
{
    if (state_ == State::Off)
        return;
    state_ = State::FadingOut;
    pendingSamples_ = fadeSamples_;
}

void MeasuredRadiation::advanceState(int n) noexcept
{
    switch (state_)
    {
    case State::WaitingForEngine:
        if (convolution_.getCurrentIRSize() > 1) // the pass-through engine has length 1
            state_ = State::EngineCrossfade, pendingSamples_ = engineCrossfadeSamples_;
        break;
    case State::EngineCrossfade:
        if ((pendingSamples_ -= n) <= 0)
            state_ = State::FadingIn, pendingSamples_ = fadeSamples_;
        break;
    default:
        break;
    }
}

void MeasuredRadiation::mix(float* modal, int n, float audioPerPascal) noexcept
{
    if (state_ == State::Off || !prepared_)
        return;
    n = std::min(n, capacity());
    float* wetData = wet_.data();
    const float* forces = force_.data();
    juce::dsp::AudioBlock<const float> input(&forces, 1, static_cast<std::size_t>(n));
    juce::dsp::AudioBlock<float> output(&wetData, 1, static_cast<std::size_t>(n));
    convolution_.process(juce::dsp::ProcessContextNonReplacing<float>(input, output));
    advanceState(n);
    for (int i = 0; i < n; ++i)
    {
        const float measured = audioPerPascal * wetData[i];
        float g = 0.0f; // share of the measured sound
        if (state_ == State::On)
            g = 1.0f;
        else if (state_ == State::FadingIn || state_ == State::FadingOut)
        {
            const float t = static_cast<float>(pendingSamples_) / static_cast<float>(fadeSamples_);
            g = state_ == State::FadingIn ? 1.0f - t : t;
            if (--pendingSamples_ <= 0)
                state_ = state_ == State::FadingIn ? State::On : State::Off;
        }
        modal[i] += g * (measured - modal[i]);
    }
}

} // namespace rosin::engine
