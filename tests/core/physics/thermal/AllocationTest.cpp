// solve(), predict() and commit() must never allocate (conventions 2 and 7): counted by replacing the global
// allocation functions of this test executable.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "core/physics/laws/FrictionLawFactory.h"
#include "core/physics/thermal/HeatBalance.h"
#include "support/AllocationCounter.h"

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
    long allocations = 0;
    double sink = 0.0;
    {
        rosin::test::AllocationCounter counter;
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
        allocations = counter.count();
    }
    EXPECT_EQ(allocations, 0);
    EXPECT_TRUE(std::isfinite(sink));
}
