#pragma once
// The radiated sound from a measured body response instead of the modal one: the bridge force convolved with
// the response (juce::dsp::Convolution, zero latency, uniform partitions). JUCE builds the convolution engine
// on its own background thread and installs it at a block boundary with a 50 ms crossfade from the engine
// before; the first engine before any response passes its input through, so the modal sound is kept until
// the response's engine is in and that crossfade is over, then this class crossfades from the modal sound to
// the measured one (and back when the response is cleared). Real-time safe after prepare(); use() and clear()
// run on the audio thread (the Convolution's loads must not interleave with its processing).
#include <vector>

#include <juce_dsp/juce_dsp.h>

namespace rosin::engine
{

class MeasuredRadiation
{
  public:
    /// Off the audio thread. A response given to use() before this is built here, before the first block.
    void prepare(double sampleRate, int maximumBlockSize);
    void reset() noexcept;

    /// Audio thread (or before prepare): start using `response` (Pa per N per sample at `sampleRate`).
    void use(juce::AudioBuffer<float>&& response, double sampleRate) noexcept;
    /// Audio thread: back to the modal sound.
    void clear() noexcept;
    int latencySamples() const noexcept { return convolution_.getLatency(); }

    /// The bridge force of sample i of the block (i < capacity()).
    void setForce(int i, float force) noexcept { force_[static_cast<std::size_t>(i)] = force; }
    int capacity() const noexcept { return static_cast<int>(force_.size()); }
    /// Replaces modal[0..n) (the modal sound, same scale) by the mix with the measured sound, scaled by
    /// `audioPerPascal`.
    void mix(float* modal, int n, float audioPerPascal) noexcept;

  private:
    enum class State
    {
        Off,
        WaitingForEngine,
        EngineCrossfade,
        FadingIn,
        On,
        FadingOut
    };
    void advanceState(int n) noexcept;

    juce::dsp::Convolution convolution_;
    std::vector<float> force_, wet_;
    State state_ = State::Off;
    int pendingSamples_ = 0; ///< left in the current wait or fade
    int fadeSamples_ = 2400, engineCrossfadeSamples_ = 3000;
    bool prepared_ = false;
};

} // namespace rosin::engine
