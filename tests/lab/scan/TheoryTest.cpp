// The theory lines of scan.json against the numbers of [Notes §6], and the boundary
// fit on a synthetic Schelleng diagram with known edges.
#include <gtest/gtest.h>

#include <cmath>

#include "lab/scan/BoundaryFit.h"
#include "lab/scan/Theory.h"

using namespace rosin::scan;

// [Notes §6.3] table, cello D string (P Z0 = 3.73e-3 kg): classical mu 1.2 / 0.35 and 0.8 / 0.3.
TEST(Theory, GuettlerWedgeMatchesTheReferenceTable)
{
    const double PZ0 = 3.73e-3;
    struct Row
    {
        double beta, ms, md, lower, upper;
    };
    for (const Row r : {Row{0.0357, 1.2, 0.35, 1.04, 1.19}, Row{0.0899, 1.2, 0.35, 2.48, 3.51},
                        Row{0.18, 1.2, 0.35, 4.48, 9.68}, Row{0.0899, 0.8, 0.3, 1.33, 1.88},
                        Row{0.18, 0.8, 0.3, 2.39, 5.22}})
    {
        const GuettlerWedge w = guettlerWedge(r.beta, r.ms, r.md, PZ0);
        EXPECT_NEAR(w.lowerAccelerationPerNewton, r.lower, 0.01) << r.beta;
        EXPECT_NEAR(w.upperAccelerationPerNewton, r.upper, 0.01) << r.beta;
    }
}

// [Notes §6.2]: a dashpot bridge (R = 5 kg/s) gives Raman's F_min = 0.374 N at v_b 0.1, beta 0.1, dmu 0.8;
// one body mode at f0 (Q 40, 0.15 kg) plus R = 100 kg/s gives 0.46 N.
TEST(Theory, MinimumForceFromTheAdmittance)
{
    const double Z0 = 0.547, f0 = 146.8, beta = 0.1;
    const double dashpot =
        fminCoefficient([](double) { return std::complex<double>(0.2, 0.0); }, f0, Z0, 0.1, 0.8);
    EXPECT_NEAR(dashpot / (beta * beta), Z0 * Z0 * 0.1 / (2.0 * 5.0 * beta * beta * 0.8), 1e-3);
    const auto mode = [&](double f)
    {
        const std::complex<double> i(0.0, 1.0);
        const double w = 2 * M_PI * f, wk = 2 * M_PI * f0;
        return i * w / (0.15 * (wk * wk - w * w + i * w * wk / 40.0)) + 1.0 / 100.0;
    };
    EXPECT_NEAR(fminCoefficient(mode, f0, Z0, 0.1, 0.8) / (beta * beta), 0.46, 0.01);
}

TEST(Theory, ScanTheoryOfTheClassicalCelloD)
{
    ScanSpec s = defaultSpec(ScanKind::Schelleng);
    s.model.friction = "classical";
    const Theory t = scanTheory(s);
    EXPECT_NEAR(t.Z0, std::sqrt(111.0 * 2.7e-3), 1e-9);
    EXPECT_DOUBLE_EQ(t.friction.muStatic, 1.2);
    EXPECT_DOUBLE_EQ(t.friction.muDynamic, 0.35);
    EXPECT_NEAR(t.fmaxCoefficient, 2.0 * t.Z0 * 0.05 / 0.85, 1e-12);
    ASSERT_TRUE(t.bridgeResistance.has_value());
    // Raman's form with the equivalent dashpot gives back the coefficient.
    EXPECT_NEAR(t.Z0 * t.Z0 * 0.05 / (2.0 * *t.bridgeResistance * 0.85), t.fminCoefficient, 1e-12);
    std::printf(
        "[figure] theory, classical cello D3 on the cello body at 0.05 m/s: c = %.4f N (F_max = c/beta), "
        "d = %.3g N (F_min = d/beta^2), equivalent bridge resistance %.1f kg/s\n",
        t.fmaxCoefficient, t.fminCoefficient, *t.bridgeResistance);
    s.model.body = "rigid";
    EXPECT_FALSE(scanTheory(s).bridgeResistance.has_value());
}

// Helmholtz exactly between F = 0.002/beta^2 and F = 0.06/beta on the default log grid: the fit recovers
// the slopes -2 and -1 (the edges are quantised to the grid, so within a grid step).
TEST(BoundaryFit, RecoversKnownEdges)
{
    const ScanSpec s = defaultSpec(ScanKind::Schelleng);
    std::vector<CellResult> results(s.cellCount());
    for (std::size_t cell = 0; cell < s.cellCount(); ++cell)
    {
        const CellSettings c = cellSettings(s, cell);
        const bool inside = c.force > 0.002 / (c.beta * c.beta) && c.force < 0.06 / c.beta;
        results[cell].regime = inside ? rosin::analysis::Regime::Helmholtz : rosin::analysis::Regime::Raucous;
    }
    const HelmholtzEdges edges = helmholtzEdges(s, results);
    const auto upper = fitLogLog(edges.upper), lower = fitLogLog(edges.lower);
    ASSERT_TRUE(upper && lower);
    EXPECT_NEAR(upper->slope, -1.0, 0.1);
    EXPECT_NEAR(lower->slope, -2.0, 0.15);
    EXPECT_NEAR(std::pow(10.0, upper->intercept), 0.06, 0.06 * 0.2);
    // Columns whose region reaches the grid's top or bottom give no point for that edge.
    EXPECT_LT(edges.upper.size() + edges.lower.size(), 40u);
    EXPECT_FALSE(fitLogLog({{0.1, 1.0}}).has_value());
}
