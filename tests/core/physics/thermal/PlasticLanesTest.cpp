// PlasticLanes (the plastic law for eight scan trials at once) against eight PlasticThermalLaw objects fed
// the same junctions: the same stick/slide decisions, friction forces and contact temperatures to rounding
// (the lanes add the stationary-side history in another order). The junctions sweep each lane through
// sticking, sliding both ways and heating: dv_h = A sin(2 pi f t), A 0.8-3.6 m/s, at 0.3-2.4 N, 2Z = 1.1
// kg/s, 0.1 s, each lane's bow lifted (no force) for a third of the time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/physics/lanes/PlasticLanes.h"
#include "core/physics/laws/FrictionLawFactory.h"

using namespace rosin::physics;

TEST(PlasticLanes, EachLaneIsThePlasticLaw)
{
    constexpr double rate = 48000.0, twoZ = 1.1;
    auto prepared = [&]
    {
        auto law = std::make_unique<PlasticThermalLaw>(galluzzoContact());
        law->prepare(rate);
        return law;
    };
    PlasticLanes lanes(prepared());
    std::vector<std::unique_ptr<PlasticThermalLaw>> laws;
    for (int l = 0; l < kLanes; ++l)
        laws.push_back(prepared());

    double worstForce = 0.0, worstTemperature = 0.0, hottest = 0.0;
    int sticking = 0, sliding = 0;
    LaneJunctionInput in;
    in.loadSlope = twoZ;
    LaneJunctionSolution out;
    for (int k = 0; k < 4800; ++k)
    {
        const double t = k / rate;
        for (int l = 0; l < kLanes; ++l)
        {
            in.bowForce[l] = (k / 800 + l) % 3 == 2 ? 0.0 : 0.3 * (l + 1); // lifted a third of the time
            in.dvHistory[l] = (0.8 + 0.4 * l) * std::sin(2.0 * std::numbers::pi * (50.0 + 20.0 * l) * t);
        }
        lanes.solve(in, out);
        for (int l = 0; l < kLanes; ++l)
        {
            const JunctionSolution s = laws[l]->solve({in.dvHistory[l], twoZ, in.bowForce[l]});
            ASSERT_EQ(out[l].sticking, s.sticking) << "lane " << l << ", sample " << k;
            (s.sticking ? sticking : sliding)++;
            worstForce = std::max(worstForce, std::abs(out[l].frictionForce - s.frictionForce) /
                                                  std::max(in.bowForce[l], 0.3));
            const double T = laws[l]->contactTemperature();
            worstTemperature = std::max(worstTemperature, std::abs(lanes.contactTemperature(l) - T));
            hottest = std::max(hottest, T);
        }
    }
    std::printf("[plastic lanes] %d sticking, %d sliding lane-samples; up to %.1f K; largest differences: "
                "friction %.2g N per N, temperature %.2g K\n",
                sticking, sliding, hottest, worstForce, worstTemperature);
    EXPECT_GT(sticking, 1000);
    EXPECT_GT(sliding, 1000);
    EXPECT_GT(hottest, 1.0);
    // Measured (vector kernels, lanes lifted a third of the time): 8.9e-16 N per N (1e-15 on
    // the baseline path) and 4.3e-14 K at up to 74 K.
    EXPECT_LT(worstForce, 1e-9);
    EXPECT_LT(worstTemperature, 1e-9);
}
