#include "BodyResponse.h"

#include <cmath>
#include <iostream>
#include <thread>

#include <juce_audio_formats/juce_audio_formats.h>
#include <juce_cryptography/juce_cryptography.h>

namespace rosin::plugin
{

namespace
{
const juce::Identifier kPathProperty{"bodyResponse"};
const juce::Identifier kHashProperty{"bodyResponseSha256"};

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

BodyResponseHandoff::BodyResponseHandoff() : pending_(std::make_unique<Pending>()) {}

void BodyResponseHandoff::offer(juce::AudioBuffer<float>&& samples, double sampleRate)
{
    for (;;)
    {
        int s = state_.load(std::memory_order_acquire);
        if (s == kTaking) // the audio thread is moving the last one out: a few instructions
        {
            std::this_thread::yield();
            continue;
        }
        if (state_.compare_exchange_strong(s, kEmpty, std::memory_order_acq_rel))
            break;
    }
    pending_->samples = std::move(samples);
    pending_->sampleRate = sampleRate;
    state_.store(kReady, std::memory_order_release);
}

void BodyResponseHandoff::requestClear()
{
    int ready = kReady;
    state_.compare_exchange_strong(ready, kEmpty, std::memory_order_acq_rel); // drop one not yet taken
    clear_.store(true, std::memory_order_release);
}

bool BodyResponseSetting::load(const juce::File& file)
{
    try
    {
        BodyResponseFile r = readBodyResponse(file);
        status_ = "measured response " + file.getFileName() + " (" + juce::String(r.samples.getNumSamples()) +
                  " samples at " + juce::String(r.sampleRate, 0) + " Hz)";
        path_ = r.path;
        sha256_ = r.sha256;
        handoff_.offer(std::move(r.samples), r.sampleRate);
        return true;
    }
    catch (const BodyResponseError& e)
    {
        status_ = e.what(); // the caller decides where to say it (editor, stderr, a CLI error)
        return false;
    }
}

void BodyResponseSetting::clear()
{
    handoff_.requestClear();
    path_.clear();
    sha256_.clear();
    status_ = "modal body (no measured response)";
}

void BodyResponseSetting::save(juce::ValueTree& state) const
{
    if (path_.isEmpty())
        return;
    state.setProperty(kPathProperty, path_, nullptr);
    state.setProperty(kHashProperty, sha256_, nullptr);
}

void BodyResponseSetting::restore(juce::ValueTree& state)
{
    const juce::String path = state.getProperty(kPathProperty).toString();
    const juce::String saved = state.getProperty(kHashProperty).toString();
    state.removeProperty(kPathProperty, nullptr);
    state.removeProperty(kHashProperty, nullptr);
    if (path.isEmpty())
    {
        clear();
        return;
    }
    const juce::File file(path);
    if (!file.existsAsFile())
    {
        clear();
        status_ = "body response " + path +
                  " is missing: the modal body plays instead (the project saved it "
                  "with SHA-256 " +
                  saved.substring(0, 12) + "...)";
        std::cerr << "rosin: " << status_ << "\n";
        return;
    }
    if (!load(file))
    {
        std::cerr << "rosin: " << status_ << "\n";
        return;
    }
    if (saved.isNotEmpty() && saved != sha256_)
    {
        status_ += "; the file changed since the project was saved";
        std::cerr << "rosin: body response " << path << " changed since the project was saved\n";
    }
}

} // namespace rosin::plugin
