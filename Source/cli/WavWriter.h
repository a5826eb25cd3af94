#pragma once
// Multichannel IEEE-float 32-bit WAV files through JUCE's WavAudioFormat. The header is JUCE-free so the
// commands that use it compile without JUCE's headers.
#include <memory>
#include <string>

namespace rosin::cli
{

class WavWriter
{
  public:
    /// Will replace `path` (relative to the working directory unless absolute) when close() succeeds; until
    /// then the samples go to a temporary file beside it, and a writer destroyed without close() leaves the
    /// old file as it was. Channels are written as a discrete layout (no speaker mask), values unchanged (no
    /// clipping, no dither). `comment` goes into the RIFF INFO comment (ICMT). Throws std::runtime_error
    /// naming the file if it cannot be created.
    WavWriter(const std::string& path, double sampleRate, int numChannels, const std::string& comment = {});
    ~WavWriter();
    WavWriter(const WavWriter&) = delete;
    WavWriter& operator=(const WavWriter&) = delete;

    /// Appends numSamples frames; channels[c] points at numSamples values. Throws on a write error.
    void write(const float* const* channels, int numSamples);
    /// Finalises the header and puts the file in place (atomically: a rename). Throws on failure.
    void close();

    int numChannels() const noexcept { return numChannels_; }
    const std::string& path() const noexcept { return path_; }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string path_;
    int numChannels_ = 0;
};

} // namespace rosin::cli
