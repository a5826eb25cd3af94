#include "instrument/plugin/BodyResponse.h"

#include <iostream>
#include <thread>

namespace rosin::plugin
{

namespace
{
const juce::Identifier kPathProperty{"bodyResponse"};
const juce::Identifier kHashProperty{"bodyResponseSha256"};
} // namespace

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
        engine::BodyResponseFile r = engine::readBodyResponse(file);
        status_ = "measured response " + file.getFileName() + " (" + juce::String(r.samples.getNumSamples()) +
                  " samples at " + juce::String(r.sampleRate, 0) + " Hz)";
        path_ = r.path;
        sha256_ = r.sha256;
        handoff_.offer(std::move(r.samples), r.sampleRate);
        return true;
    }
    catch (const engine::BodyResponseError& e)
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
