// Physics check (b): Guettler scans at beta = 0.0899 ([Galluzzo2017] Figs. 6-8 column e, 20 x 20, 0.5 s
// trials, the cello D3 of the Galluzzo rig on the cello body) with the three friction models of
// [Galluzzo2017]. The paper finds the reconstructed curve "significantly better" than the classical one and
// the thermal (plastic) model "rather more benign than the reconstructed ... and a great deal more so than
// the original friction curve". Measured: the fraction of cells reaching Helmholtz motion within 20 periods
// of the first slip.
//
// Found (see the [figure] line): plastic > reconstructed > classical, as in [Galluzzo2017], once the
// transient counts only full flybacks (scan::kFlybackShare): the plastic law's short reversals at a slow bow
// had counted as flybacks and broke its Helmholtz runs (then 5.0 % plastic against 5.5 % reconstructed). The
// ranking holds for shares 0.15-0.35 (plastic 11-19 %, reconstructed 5.5-6 %, classical 2.75-3 %), and at
// larger beta the plastic law is far ahead.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/config/TempFiles.h"
#include "lab/scan/CsvRow.h"
#include "lab/scan/RunFiles.h"
#include "lab/scan/ScanRun.h"

using namespace rosin::scan;

namespace ROSIN_FILE_LOCAL
{
class GuettlerScan : public ::testing::Test
{
  protected:
    static void SetUpTestSuite()
    {
        dir_ = std::make_unique<rosin::test::TempDir>();
        for (const char* law : {"classical", "reconstructed", "plastic"})
        {
            ScanSpec spec = defaultSpec(ScanKind::Guettler);
            spec.model.friction = law;
            spec.betas = {0.0899};
            RunOptions o;
            o.output.figures = false;
            o.progress = false;
            std::ostringstream out, err;
            const std::string dir = dir_->path() + "/" + law;
            ASSERT_TRUE(runScan(spec, dir, o, out, err).complete);
            reached_[law] =
                nlohmann::json::parse(readTextFile(dir + "/scan.json"))["reachedFraction"].get<double>();
            spec_ = spec;
        }
    }
    static void TearDownTestSuite() { dir_.reset(); }

    // Made in SetUpTestSuite, not at static initialisation: every test runs in a process of its own and
    // the other suites of this binary would leave an empty folder each.
    static inline std::unique_ptr<rosin::test::TempDir> dir_;
    static inline std::map<std::string, double> reached_;
    static inline ScanSpec spec_; ///< the last law's (plastic)
};

TEST_F(GuettlerScan, FrictionCurvesRankAsInTheSeed)
{
    const double classical = reached_["classical"], reconstructed = reached_["reconstructed"],
                 plastic = reached_["plastic"];
    EXPECT_GT(reconstructed, classical);
    std::printf(
        "[figure] Guettler scans at beta 0.0899 (20x20, 0.5 s): Helmholtz within 20 periods in %.1f %% of "
        "cells (plastic), %.1f %% (reconstructed), %.1f %% (classical); seed ranking plastic > "
        "reconstructed > classical: %s\n",
        100.0 * plastic, 100.0 * reconstructed, 100.0 * classical,
        plastic > reconstructed && reconstructed > classical ? "reproduced" : "NOT reproduced");
}

// [Galluzzo2017]'s full ranking: the thermal law is "rather more benign than the reconstructed".
TEST_F(GuettlerScan, PlasticBeatsReconstructed)
{
    EXPECT_GT(reached_["plastic"], reached_["reconstructed"]);
}

// [Galluzzo2017] on Fig. 12a (the classical curve, beta 0.0899, 300 x 300): "roughly a quarter of the samples
// classified as successful". Rosin's replica of that scan reaches Helmholtz motion within 20 periods in 2.9 %
// of the cells, and an independent reflection-function simulator in 3.5 %: the models agree with
// each other, not with [Galluzzo2017]. Fig. 12 hatches "unsuccessful simulations" and shades the rest by
// transient length, black for 20 periods or more, so "successful" there can mean "reaches Helmholtz motion at
// all". Counted that way, whole 0.5 s trials end in Helmholtz motion in 18.0 % of the 90,000 cells (measured
// with `rosin scan guettler --friction classical --beta 0.0899 --grid 300 --full-trials`), [Galluzzo2017]'s
// order. Here on the 20 x 20 grid: most of the classical curve's Helmholtz cells take longer than the cap
// (measured: 19.0 % end in Helmholtz motion, 2.8 % reach it within 20 periods), and the share is of
// [Galluzzo2017]'s order.
TEST(GuettlerScanWholeTrials, MostClassicalHelmholtzCellsTakeLongerThanTheCap)
{
    ScanSpec spec = defaultSpec(ScanKind::Guettler);
    spec.model.friction = "classical";
    spec.betas = {0.0899};
    spec.trialEnd = GuettlerTrialEnd::Whole;
    RunOptions o;
    o.output.figures = false;
    o.progress = false;
    std::ostringstream out, err;
    rosin::test::TempDir dir;
    ASSERT_TRUE(runScan(spec, dir.path(), o, out, err).complete);
    const auto j = nlohmann::json::parse(readTextFile(dir.path() + "/scan.json"));
    const auto& beta = j["perBeta"].at(0);
    const double cells = beta["cells"].get<double>();
    const double endsInHelmholtz = beta["helmholtzCells"].get<double>() / cells;
    const double withinCap = beta["reachedCells"].get<double>() / cells;
    std::printf(
        "[figure] classical, beta 0.0899, whole 0.5 s trials: %.1f %% of cells end in Helmholtz motion, "
        "%.1f %% reach it within 20 periods ([Galluzzo2017]: roughly a quarter successful)\n",
        100.0 * endsInHelmholtz, 100.0 * withinCap);
    EXPECT_GT(endsInHelmholtz, 4.0 * withinCap);
    EXPECT_GT(endsInHelmholtz, 0.125); // [Galluzzo2017]'s order: within a factor 2 of a quarter
    EXPECT_LT(endsInHelmholtz, 0.5);
}

// [Galluzzo2017] classifies simulated trials with the algorithm it uses on measurements, from the bridge
// force.
// `--classify bridge-force` does so (criteria fixed before this comparison: [Notes §7.2] onsets with Rosin's
// 0.15 P refractory time, the same [Notes §7.3] transient rule, window from the first onset). A second
// method: for the plastic law it must agree with the state's reached-or-not in most cells (measured: 359 of
// 400). Shares measured with it at beta 0.0899: plastic 17.0 %, classical 1.5 %, reconstructed 0.0 % (the
// reconstructed curve's partial slips, ~500 a second, read as extra slips in the force), so [Galluzzo2017]'s
// ranking does not hold under this classification: plastic > classical > reconstructed.
TEST_F(GuettlerScan, BridgeForceClassificationAgreesWithTheStateForThePlasticLaw)
{
    ScanSpec spec = spec_;
    ASSERT_EQ(spec.model.friction, "plastic");
    spec.classification = Classification::BridgeForce;
    spec.trialEnd = GuettlerTrialEnd::AfterWindow;
    RunOptions o;
    o.output.figures = false;
    o.progress = false;
    std::ostringstream out, err;
    const std::string dir = dir_->path() + "/plastic-bridge-force";
    ASSERT_TRUE(runScan(spec, dir, o, out, err).complete);
    const RowMap fromForce = readRowsFile(dir + "/scan.csv", spec, false);
    const RowMap fromState = readRowsFile(dir_->path() + "/plastic/scan.csv", spec_, false);
    ASSERT_EQ(fromForce.size(), fromState.size());
    const auto reached = [](const std::string& line)
    {
        const CellResult r = parseRow(line);
        return r.transientPeriods && *r.transientPeriods < 20.0;
    };
    int agree = 0, reachedByForce = 0;
    for (const auto& [cell, row] : fromState)
    {
        agree += reached(row) == reached(fromForce.at(cell));
        reachedByForce += reached(fromForce.at(cell));
    }
    std::printf("[figure] plastic, beta 0.0899, bridge-force classification: reached in %d of %zu cells; "
                "reached-or-not agrees with the state's in %d\n",
                reachedByForce, fromState.size(), agree);
    EXPECT_GE(agree, static_cast<int>(0.8 * static_cast<double>(fromState.size())));
    EXPECT_GT(reachedByForce, 0);
}

} // namespace ROSIN_FILE_LOCAL
