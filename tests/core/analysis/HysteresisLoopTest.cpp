// The hysteresis-loop recorder against geometry: a circle traversed anticlockwise in the (dv, f) plane
// encloses pi r^2 per turn with a positive sign, clockwise with a negative one; only the chosen interval is
// kept, and the CSV holds one row per kept sample.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "core/analysis/HysteresisLoop.h"

namespace rosin::analysis
{
namespace ROSIN_FILE_LOCAL
{

TEST(HysteresisLoop, AreaOfACircleHasTheSenseOfTraversal)
{
    const double fs = 1000.0, r = 0.2;
    for (const double sense : {1.0, -1.0})
    {
        HysteresisLoop loop(1.0, 3.0, fs); // two turns of a 1 Hz circle
        for (int k = 0; k < 4000; ++k)
        {
            physics::VoiceSample s;
            const double phase = 2.0 * M_PI * k / fs;
            s.bowVelocity = 0.1;
            s.bowPointVelocity = 0.1 + r * std::cos(phase);
            s.frictionForce = r * sense * std::sin(phase);
            s.sticking = false;
            loop.add(s);
        }
        EXPECT_EQ(loop.points().size(), 2000u);
        EXPECT_NEAR(loop.signedArea(), sense * 2.0 * M_PI * r * r, 1e-3);
        EXPECT_DOUBLE_EQ(loop.stickingFraction(), 0.0);
    }
}

TEST(HysteresisLoop, WritesOneCsvRowPerKeptSample)
{
    HysteresisLoop loop(0.01, 0.02, 1000.0);
    for (int k = 0; k < 50; ++k)
        loop.add(physics::VoiceSample{});
    std::istringstream in(loop.csv());
    std::string header, line;
    std::getline(in, header);
    EXPECT_EQ(header, "time,slidingSpeed,frictionForce,contactTemperature");
    int rows = 0;
    while (std::getline(in, line))
        ++rows;
    EXPECT_EQ(rows, 10);
    EXPECT_DOUBLE_EQ(loop.stickingFraction(), 1.0);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::analysis
