#pragma once
// The plugin's measured body response (engine/BodyResponseFile.h reads it): read and checked on the message
// thread, handed to the audio thread without locks or allocation there (BodyResponseHandoff), and saved with
// the state (path and content hash).
#include <atomic>
#include <memory>

#include <juce_audio_basics/juce_audio_basics.h>
#include <juce_data_structures/juce_data_structures.h>

#include "instrument/engine/BodyResponseFile.h"

namespace rosin::plugin
{

/// One response at a time from the message thread to the audio thread. offer() and requestClear() run on
/// one thread (the message thread); collect() on the audio thread, where it moves the samples out without
/// allocating or locking.
class BodyResponseHandoff
{
  public:
    BodyResponseHandoff();
    /// Replaces any response not yet collected.
    void offer(juce::AudioBuffer<float>&& samples, double sampleRate);
    void requestClear();

    template <typename Use, typename Clear> void collect(Use&& use, Clear&& clear) noexcept
    {
        if (clear_.exchange(false, std::memory_order_acq_rel))
            clear();
        int ready = kReady;
        if (!state_.compare_exchange_strong(ready, kTaking, std::memory_order_acq_rel))
            return;
        use(std::move(pending_->samples), pending_->sampleRate);
        state_.store(kTaken, std::memory_order_release);
    }

  private:
    enum
    {
        kEmpty,
        kReady,
        kTaking,
        kTaken
    };
    struct Pending
    {
        juce::AudioBuffer<float> samples;
        double sampleRate = 0.0;
    };
    std::unique_ptr<Pending> pending_; ///< allocated once; the audio thread only moves out of it
    std::atomic<int> state_{kEmpty};
    std::atomic<bool> clear_{false};
};

/// The processor's measured body response on the message thread: which file, its content hash, and what
/// happened last (for the editor). Loads go to the audio thread through the handoff.
class BodyResponseSetting
{
  public:
    explicit BodyResponseSetting(BodyResponseHandoff& handoff) : handoff_(handoff) {}
    /// Reads and hands over `file`. False (and the reason, naming the file, in status()) if it cannot be
    /// used; the response in use stays.
    bool load(const juce::File& file);
    /// Back to the modal body's sound.
    void clear();
    /// State properties "bodyResponse" (path) and "bodyResponseSha256", absent without a response.
    void save(juce::ValueTree& state) const;
    /// Loads the response a saved state names (and removes the properties from `state`). A missing file
    /// leaves the modal sound and says so; a file whose content changed since is loaded, with a warning.
    void restore(juce::ValueTree& state);
    juce::String path() const { return path_; }
    juce::String status() const { return status_; }

  private:
    BodyResponseHandoff& handoff_;
    juce::String path_, sha256_;
    juce::String status_ = "modal body (no measured response)";
};

} // namespace rosin::plugin
