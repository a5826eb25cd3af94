#pragma once
// Counts heap allocations (operator new, any form) made by the calling thread while alive. The global
// operators are replaced in PluginTestMain.cpp. Thread-local, so JUCE's timer and message threads do not
// disturb the count of the "audio" thread under test. (Aligned new and malloc are not counted; JUCE and the
// physics use neither on the audio path.)
namespace rosin::test
{
extern thread_local bool countThisThread;
extern thread_local long threadAllocations;

struct ThreadAllocationCounter
{
    ThreadAllocationCounter() { threadAllocations = 0, countThisThread = true; }
    ~ThreadAllocationCounter() { countThisThread = false; }
    ThreadAllocationCounter(const ThreadAllocationCounter&) = delete;
    ThreadAllocationCounter& operator=(const ThreadAllocationCounter&) = delete;
    long count() const { return threadAllocations; }
};
} // namespace rosin::test
