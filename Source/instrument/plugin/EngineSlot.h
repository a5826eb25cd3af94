#pragma once
// Hands a freshly built instrument to the audio thread without a lock, and takes the old one back to be
// freed elsewhere (the chowdsp / Surge pattern).
//
//   builder thread (message thread, prepareToPlay):  build -> publish()        collect() frees retired
//   audio thread (processBlock):                      acquire(): pending -> active, old active -> retired
//
// The audio thread only exchanges two atomics and never frees. It swaps only when the retired slot is empty,
// so at most three engines exist. Builder-side calls must come from one thread at a time (the processor
// serialises them with a mutex the audio thread never touches).
#include <array>
#include <atomic>
#include <memory>

#include "instrument/engine/Engine.h"

namespace rosin::plugin
{

using engine::Engine;

class EngineSlot
{
  public:
    EngineSlot() = default;
    ~EngineSlot();
    EngineSlot(const EngineSlot&) = delete;
    EngineSlot& operator=(const EngineSlot&) = delete;

    // --- builder side ---
    /// Offers a new engine; an engine offered earlier and not yet taken is freed.
    void publish(std::unique_ptr<Engine> engine);
    /// Frees the engine the audio thread retired, if any.
    void collect();
    /// Only while the audio thread is stopped (prepareToPlay, releaseResources): install directly.
    void installNow(std::unique_ptr<Engine> engine);

    // --- audio thread ---
    /// Takes a pending engine if there is one and returns the active engine (may be null). Wait-free.
    Engine* acquire() noexcept;
    Engine* active() const noexcept { return active_; }

  private:
    std::atomic<Engine*> pending_{nullptr};
    std::atomic<Engine*> retired_{nullptr};
    Engine* active_ = nullptr;
};

} // namespace rosin::plugin
