#include "instrument/engine/BodyResponseFile.h"

#include <cmath>

#include <juce_audio_formats/juce_audio_formats.h>
#include <juce_cryptography/juce_cryptography.h>

namespace rosin::engine
{

namespace
{
[[noreturn]] void fail(const juce::File& file, const juce::String& what)
{
    throw BodyResponseError(("body response " + file.getFullPathName() + ": " + what).toStdString());
}
} // namespace

juce::String fileSha256(const juce::File& file)
{
    juce::FileInputStream in(file);
    if (!in.openedOk())
        return {};
    return juce::SHA256(in).toHexString();
}

BodyResponseFile readBodyResponse(const juce::File& file)
{
    if (!file.existsAsFile())
        fail(file, "expected an existing audio file (WAV, AIFF or FLAC), but it is missing");
    juce::AudioFormatManager formats;
    formats.registerBasicFormats();
    const std::unique_ptr<juce::AudioFormatReader> reader(formats.createReaderFor(file));
    if (reader == nullptr)
        fail(file, "expected a WAV, AIFF or FLAC file, but it could not be read as one");
    const auto length = reader->lengthInSamples;
    if (length < kMinimumResponseSamples)
        fail(file, "expected at least " + juce::String(kMinimumResponseSamples) + " samples, but it has " +
                       juce::String(length));
    if (static_cast<double>(length) > kMaximumResponseSeconds * reader->sampleRate)
        fail(file, "expected at most " + juce::String(kMaximumResponseSeconds) + " s, but it lasts " +
                       juce::String(static_cast<double>(length) / reader->sampleRate, 2) + " s");
    BodyResponseFile r;
    r.samples.setSize(1, static_cast<int>(length));
    reader->read(&r.samples, 0, static_cast<int>(length), 0, true, false);
    r.sampleRate = reader->sampleRate;
    const float* x = r.samples.getReadPointer(0);
    bool nonzero = false;
    for (int i = 0; i < r.samples.getNumSamples(); ++i)
    {
        if (!std::isfinite(x[i]))
            fail(file, "expected finite samples, but sample " + juce::String(i) + " is not");
        nonzero = nonzero || x[i] != 0.0f;
    }
    if (!nonzero)
        fail(file, "expected a response, but every sample is zero");
    r.path = file.getFullPathName();
    r.sha256 = fileSha256(file);
    return r;
}

} // namespace rosin::engine
