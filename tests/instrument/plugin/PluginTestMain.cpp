// test_plugin's main: JUCE's message manager for the processor's timers (never dispatched: the tests service
// engine builds themselves), and the replaced global operator new that AllocationCounter reads.
#include <gtest/gtest.h>

#include <juce_events/juce_events.h>

#include "instrument/plugin/ThreadAllocationCounter.h"

int main(int argc, char** argv)
{
    juce::ScopedJuceInitialiser_GUI juce;
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

namespace rosin::test
{
thread_local bool countThisThread = false;
thread_local long threadAllocations = 0;
} // namespace rosin::test

namespace
{
void* allocate(std::size_t size)
{
    if (rosin::test::countThisThread)
        ++rosin::test::threadAllocations;
    if (void* p = std::malloc(size ? size : 1))
        return p;
    throw std::bad_alloc();
}
} // namespace

void* operator new(std::size_t size)
{
    return allocate(size);
}
void* operator new[](std::size_t size)
{
    return allocate(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
    if (rosin::test::countThisThread)
        ++rosin::test::threadAllocations;
    return std::malloc(size ? size : 1);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept
{
    if (rosin::test::countThisThread)
        ++rosin::test::threadAllocations;
    return std::malloc(size ? size : 1);
}
void operator delete(void* p) noexcept
{
    std::free(p);
}
void operator delete[](void* p) noexcept
{
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept
{
    std::free(p);
}
