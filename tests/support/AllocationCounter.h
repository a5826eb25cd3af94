#pragma once
// Counts heap allocations made while an AllocationCounter is alive, to prove that real-time code paths never
// allocate. It replaces the global operator new/delete of the test executable, so include this header in
// exactly ONE source file of each test executable.
#include <atomic>
#include <cstdlib>
#include <new>

namespace rosin::test
{
inline std::atomic<bool> countingAllocations{false};
inline std::atomic<long> allocationsWhileCounting{0};

/// Counts allocations from construction to destruction (not nestable).
struct AllocationCounter
{
    AllocationCounter() { allocationsWhileCounting = 0, countingAllocations = true; }
    ~AllocationCounter() { countingAllocations = false; }
    AllocationCounter(const AllocationCounter&) = delete;
    AllocationCounter& operator=(const AllocationCounter&) = delete;
    long count() const { return allocationsWhileCounting.load(); }
};
} // namespace rosin::test

void* operator new(std::size_t size)
{
    if (rosin::test::countingAllocations.load(std::memory_order_relaxed))
        rosin::test::allocationsWhileCounting.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size ? size : 1))
        return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept
{
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
    std::free(p);
}
