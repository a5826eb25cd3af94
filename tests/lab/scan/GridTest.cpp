// The default grids of [Galluzzo2017] (section 3: Schelleng 20 x 20 log-spaced, Guettler 20 x 20 linear at
// the eight betas of Fig. 5) and the cell numbering of Resources/docs/scan-format.md.
#include <gtest/gtest.h>

#include <cmath>

#include "lab/scan/Axis.h"
#include "lab/scan/ScanSpec.h"

using namespace rosin::scan;

TEST(Grid, SchellengDefaultsAreSeedLogGrid)
{
    const ScanSpec s = defaultSpec(ScanKind::Schelleng);
    ASSERT_EQ(s.forces.size(), 20u);
    ASSERT_EQ(s.betas.size(), 20u);
    ASSERT_EQ(s.second.size(), 1u);
    EXPECT_DOUBLE_EQ(s.forces.front(), 0.1);
    EXPECT_DOUBLE_EQ(s.forces.back(), 3.0);
    EXPECT_DOUBLE_EQ(s.betas.front(), 0.02);
    EXPECT_DOUBLE_EQ(s.betas.back(), 0.18);
    EXPECT_DOUBLE_EQ(s.second.front(), 0.05);
    // Log spacing: a constant ratio, (3/0.1)^(1/19) for the forces.
    const double ratio = std::pow(30.0, 1.0 / 19.0);
    for (std::size_t i = 1; i < 20; ++i)
        EXPECT_NEAR(s.forces[i] / s.forces[i - 1], ratio, 1e-12);
    EXPECT_NEAR(s.betas[10] / s.betas[9], std::pow(9.0, 1.0 / 19.0), 1e-12);
    EXPECT_EQ(s.cellCount(), 400u);
    EXPECT_DOUBLE_EQ(s.trialSeconds, 1.0);
    EXPECT_EQ(s.model.preset, "galluzzo-rig");
    EXPECT_EQ(s.model.string.name, "cello-D3");
}

TEST(Grid, GuettlerDefaultsAreSeedLinearGridAtEightBetas)
{
    const ScanSpec s = defaultSpec(ScanKind::Guettler);
    ASSERT_EQ(s.forces.size(), 20u);
    ASSERT_EQ(s.second.size(), 20u);
    EXPECT_DOUBLE_EQ(s.forces.front(), 0.4);
    EXPECT_DOUBLE_EQ(s.forces.back(), 3.2);
    EXPECT_DOUBLE_EQ(s.second.front(), 0.08);
    EXPECT_DOUBLE_EQ(s.second.back(), 3.2);
    // Linear spacing: a constant step.
    for (std::size_t i = 1; i < 20; ++i)
    {
        EXPECT_NEAR(s.forces[i] - s.forces[i - 1], 2.8 / 19.0, 1e-12);
        EXPECT_NEAR(s.second[i] - s.second[i - 1], 3.12 / 19.0, 1e-12);
    }
    const std::vector<double> seed = {0.0357, 0.0449, 0.0566, 0.0714, 0.0899, 0.1133, 0.1428, 0.18};
    EXPECT_EQ(s.betas, seed);
    EXPECT_EQ(s.cellCount(), 3200u);
    EXPECT_DOUBLE_EQ(s.trialSeconds, 0.5);
    EXPECT_EQ(s.model.friction, "plastic");
}

TEST(Grid, SingleValueAxes)
{
    EXPECT_EQ(linearAxis(0.5, 2.0, 1), std::vector<double>{0.5});
    EXPECT_EQ(logAxis(0.5, 2.0, 1), std::vector<double>{0.5});
    EXPECT_EQ(logAxis(1.0, 4.0, 3), (std::vector<double>{1.0, 2.0, 4.0}));
}

TEST(Grid, CellIndexFollowsTheContract)
{
    ScanSpec g = defaultSpec(ScanKind::Guettler);
    g.betas = {0.05, 0.1, 0.15};
    g.forces = linearAxis(1.0, 4.0, 4);
    g.second = linearAxis(0.5, 2.5, 5);
    // cell = (iBeta * nForce + iForce) * nAcceleration + iAcceleration
    EXPECT_EQ(cellIndex(g, {2, 3, 4}), (2u * 4u + 3u) * 5u + 4u);
    for (std::size_t cell = 0; cell < g.cellCount(); ++cell)
    {
        const CellCoordinates c = coordinatesOf(g, cell);
        EXPECT_EQ(cellIndex(g, c), cell);
    }
    const CellSettings s = cellSettings(g, (1 * 4 + 2) * 5 + 3);
    EXPECT_DOUBLE_EQ(s.beta, 0.1);
    EXPECT_DOUBLE_EQ(s.force, 3.0);
    EXPECT_DOUBLE_EQ(s.second, 2.0);

    // Schelleng: one bow speed, cell = iBeta * nForce + iForce.
    const ScanSpec sch = defaultSpec(ScanKind::Schelleng);
    const CellSettings last = cellSettings(sch, 399);
    EXPECT_DOUBLE_EQ(last.beta, 0.18);
    EXPECT_DOUBLE_EQ(last.force, 3.0);
    EXPECT_EQ(cellIndex(sch, {7, 11, 0}), 7u * 20u + 11u);
}
