// solve(), predict() and commit() must never allocate (conventions 2 and 7): counted by replacing the global
// allocation functions of this test executable.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "physics/friction/FrictionLawFactory.h"
#include "physics/thermal/HeatBalance.h"

namespace
{
std::atomic<long> gAllocations{0};
std::atomic<bool> gCounting{false};
} // namespace

void* operator new(std::size_t n)
{
    if (gCounting.load(std::memory_order_relaxed))
        gAllocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(n ? n : 1))
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

using namespace rosin::physics;

TEST(Allocation, ThermalLawsAndHeatBalanceDoNotAllocatePerSample)
{
    std::vector<std::unique_ptr<FrictionLaw>> laws;
    for (const auto& n : frictionModelNames())
    {
        laws.push_back(makeFrictionLaw(frictionModelFromName(n), galluzzoContact()));
        laws.back()->prepare(48000.0);
    }
    HeatBalance heat;
    heat.prepare(galluzzoContact(), 48000.0);
    gAllocations = 0;
    gCounting = true;
    double sink = 0.0;
    for (int k = 0; k < 20000; ++k)
    {
        const double dvh = 0.3 * std::sin(0.01 * k);
        for (auto& law : laws)
            sink += law->solve({dvh, 0.84, 1.0 + 0.5 * std::sin(0.001 * k)}).frictionForce;
        sink += heat.predict(0.1, 0.2, 1.0);
        heat.commit(0.1, 0.2, 1.0);
        if (k == 10000)
            for (auto& law : laws)
                law->reset();
    }
    gCounting = false;
    EXPECT_EQ(gAllocations.load(), 0);
    EXPECT_TRUE(std::isfinite(sink));
}
