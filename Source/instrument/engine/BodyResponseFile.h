#pragma once
// A measured body response: the impulse response from the bridge force (N) to the sound pressure (Pa) a
// microphone hears, read from an audio file and checked (off the audio thread). The plugin hands it to its
// audio thread (plugin/BodyResponse.h); the offline render gives it to the output stage directly.
#include <stdexcept>

#include <juce_audio_basics/juce_audio_basics.h>

namespace rosin::engine
{

/// What was wrong with a response file; the message names the file and what was expected.
class BodyResponseError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

struct BodyResponseFile
{
    juce::AudioBuffer<float> samples; ///< one channel, Pa per N per sample
    double sampleRate = 0.0;
    juce::String path;   ///< absolute
    juce::String sha256; ///< of the file's bytes, hex
};

inline constexpr int kMinimumResponseSamples = 64;
inline constexpr double kMaximumResponseSeconds = 10.0;

/// Reads `file` (WAV, AIFF or FLAC; the first channel of a multichannel file). Throws BodyResponseError when
/// the file is missing or unreadable, has fewer than kMinimumResponseSamples samples or more than
/// kMaximumResponseSeconds, or holds a non-finite or all-zero signal.
BodyResponseFile readBodyResponse(const juce::File& file);

/// SHA-256 of a file's bytes, hex; empty if it cannot be read.
juce::String fileSha256(const juce::File& file);

} // namespace rosin::engine
