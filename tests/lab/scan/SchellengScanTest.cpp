// Physics check (a): a Schelleng scan of the classical friction curve ([Galluzzo2017] Fig. 3b: the cello D3
// of the Galluzzo rig on the cello body, default 20 x 20 grid, 0.05 m/s, 1 s trials) against Schelleng's
// theory
// ([Notes §6.1-6.2]): the Helmholtz region's upper edge F_max = 2 Z0 v_b / (beta (mu_s - mu_d)) has slope -1
// on log-log axes, the lower edge F_min ~ 1/beta^2 slope -2.
//
// Found (see the [figure] lines): the upper edge follows -1 and lies within a factor 2 of the theory; the
// lower edge does not follow -2 (about -0.8). It is not Raman's body-resistance limit: F_min from the body
// ([Notes] eq. 6.5, d ~ 2e-4 N) is below the grid for beta > 0.05, the same lower edge appears with a rigid
// bridge, and longer trials (2 s) or a start inside Guettler's wedge do not change it. What sets it instead
// is measured in StickingRippleTest.cpp: in steady Helmholtz motion the sticking friction force carries a
// ripple 8-21x the excursion eq. 6.5 assumes, scaling like v_b / beta (the corner's jump, as F_max does), so
// the lower edge it sets runs nearly parallel to the upper edge. The -2 expectation is retired (it is
// Schelleng's theory, not a seed result): the lower edge is checked against F_min with the model's own
// losses. Also tried (throwaway drivers, classical, default grid): a start "tailored to elicit steady
// Helmholtz motion" ([Galluzzo2017] section 2.2): attack at F0 inside the region (0.39 F_max, or the
// geometric mean of the theory's F_min and F_max; acceleration 0.5 m/s^2 or the middle of Guettler's wedge
// for F0), hold, glide the force to N over 0.2 s, judge the last 0.45 s of 1.2 s. Helmholtz motion
// established at F0 still falls into double slipping or raucous motion at 0.1-0.3 N for most betas above 0.04
// (fitted lower slopes -0.7 to -3.1 depending on F0 and the fit rule); 96 kHz, a rigid bridge, no torsion or
// no bending stiffness do not give a clean -2 either, nor does the less certain loss scale eta_B x 1e-2
// (-1.15). With the other laws the same scan gives lower slopes of -1.39 (reconstructed) and -1.64 (plastic).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/config/TempFiles.h"
#include "lab/scan/RunFiles.h"
#include "lab/scan/ScanRun.h"

using namespace rosin::scan;

namespace ROSIN_FILE_LOCAL
{
class SchellengScan : public ::testing::Test
{
  protected:
    static void SetUpTestSuite()
    {
        dir_ = std::make_unique<rosin::test::TempDir>();
        ScanSpec spec = defaultSpec(ScanKind::Schelleng);
        spec.model.friction = "classical";
        RunOptions o;
        o.output.figures = false;
        o.progress = false;
        std::ostringstream out, err;
        const RunReport r = runScan(spec, dir_->path(), o, out, err);
        ASSERT_TRUE(r.complete);
        summary_ = nlohmann::json::parse(readTextFile(dir_->path() + "/scan.json"));
    }
    static void TearDownTestSuite() { dir_.reset(); }

    // The fitted edge's force at beta, N.
    static double fitted(const char* edge, double beta)
    {
        const auto& b = summary_["boundaries"][edge];
        return std::pow(10.0, b["intercept"].get<double>() + b["slope"].get<double>() * std::log10(beta));
    }

    // Made in SetUpTestSuite, not at static initialisation: every test runs in a process of its own and
    // the other suites of this binary would leave an empty folder each.
    static inline std::unique_ptr<rosin::test::TempDir> dir_;
    static inline nlohmann::json summary_;
};

TEST_F(SchellengScan, UpperBoundaryFollowsSchellengsMaximumForce)
{
    const auto& upper = summary_["boundaries"]["upper"];
    const auto& lower = summary_["boundaries"]["lower"];
    ASSERT_TRUE(upper.is_object());
    ASSERT_TRUE(lower.is_object());
    const double c = summary_["theory"]["fmaxCoefficient"].get<double>();
    const double betaMid = std::sqrt(0.02 * 0.18); // the grid's middle on a log axis
    const double ratio = fitted("upper", betaMid) / (c / betaMid);
    EXPECT_NEAR(upper["slope"].get<double>(), -1.0, 0.35);
    EXPECT_GT(ratio, 0.5);
    EXPECT_LT(ratio, 2.0);
    std::printf(
        "[figure] Schelleng scan, classical, cello D3 + body, 20x20, 1 s: Helmholtz %.1f %% of cells; "
        "upper edge slope %.3f (%d columns), at beta %.3f %.3f N = %.2f x theory 2 Z0 v_b/(beta dmu) "
        "%.3f N; lower edge slope %.3f (%d columns; Schelleng's theory: -2), at beta %.3f %.3f N vs "
        "theory d/beta^2 %.3f N\n",
        100.0 * summary_["helmholtzFraction"].get<double>(), upper["slope"].get<double>(),
        upper["points"].get<int>(), betaMid, fitted("upper", betaMid), ratio, c / betaMid,
        lower["slope"].get<double>(), lower["points"].get<int>(), betaMid, fitted("lower", betaMid),
        summary_["theory"]["fminCoefficient"].get<double>() / (betaMid * betaMid));
}

// Schelleng's -2 is his theory, not a seed result ([Notes §6.2]): the lower edge is tested against what the
// theory can promise for this model, F_min of eq. 6.5 with the model's own losses (body and string), below
// which Helmholtz motion cannot survive: a necessary bound, which every Helmholtz cell must respect.
// Measured: the lowest Helmholtz force of each beta column is 1.95-8.5x that bound, ~2x at beta <= 0.057,
// where the bound's -2 slope is steep, and up to 8.5x at large beta, where the sticking ripple sets the edge
// (StickingRippleTest.cpp) and the grid's 0.1 N floor is reached.
TEST_F(SchellengScan, EveryHelmholtzCellLiesAboveTheMinimumForceOfTheModelsOwnLosses)
{
    const double d = summary_["theory"]["fminTotalCoefficient"].get<double>();
    ASSERT_GT(d,
              summary_["theory"]["fminCoefficient"].get<double>()); // the string's losses add to the body's
    std::istringstream csv(readTextFile(dir_->path() + "/scan.csv"));
    std::string line;
    std::getline(csv, line); // cell,beta,bowForce,bowSpeed,regime,...
    ASSERT_EQ(line.rfind("cell,beta,bowForce,bowSpeed,regime,", 0), 0u) << line;
    double tightest = 1e300;
    int helmholtz = 0;
    while (std::getline(csv, line))
    {
        std::istringstream row(line);
        std::string cell, beta, force, speed, regime;
        std::getline(row, cell, ','), std::getline(row, beta, ','), std::getline(row, force, ',');
        std::getline(row, speed, ','), std::getline(row, regime, ',');
        if (regime != "helmholtz")
            continue;
        ++helmholtz;
        const double b = std::stod(beta);
        tightest = std::min(tightest, std::stod(force) / (d / (b * b)));
    }
    std::printf(
        "[figure] %d Helmholtz cells; the closest lies at %.2f x F_min (eq. 6.5, body + string losses, "
        "d = %.3g N)\n",
        helmholtz, tightest, d);
    ASSERT_GT(helmholtz, 20);
    EXPECT_GT(tightest, 1.0);
}

} // namespace ROSIN_FILE_LOCAL
