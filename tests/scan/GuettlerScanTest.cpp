// Physics check (b): Guettler scans at beta = 0.0899 (seed 001 Figs. 6-8 column e, 20 x 20, 0.5 s trials,
// the cello D3 of the Galluzzo rig on the cello body) with the three friction models of the seed. The seed
// finds the reconstructed curve "significantly better" than the classical one and the thermal (plastic) model
// "rather more benign than the reconstructed ... and a great deal more so than the original friction curve".
// Measured: the fraction of cells reaching Helmholtz motion within 20 periods of the first slip.
//
// Found (see the [figure] line): plastic > reconstructed > classical, as in the seed, once the transient
// counts only full flybacks (scan::kFlybackShare): the plastic law's short reversals at a slow bow had
// counted as flybacks and broke its Helmholtz runs (then 5.0 % plastic against 5.5 % reconstructed). The
// ranking holds for shares 0.15-0.35 (plastic 11-19 %, reconstructed 5.5-6 %, classical 2.75-3 %), and at
// larger beta the plastic law is far ahead.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "config/TempFiles.h"
#include "lab/scan/RunFiles.h"
#include "lab/scan/ScanRun.h"

using namespace rosin::scan;

namespace
{
class GuettlerScan : public ::testing::Test
{
  protected:
    static void SetUpTestSuite()
    {
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
        }
    }
    static void TearDownTestSuite() { delete dir_; }

    static inline rosin::test::TempDir* dir_ = new rosin::test::TempDir;
    static inline std::map<std::string, double> reached_;
};
} // namespace

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

// The seed's full ranking: the thermal law is "rather more benign than the reconstructed".
TEST_F(GuettlerScan, PlasticBeatsReconstructed)
{
    EXPECT_GT(reached_["plastic"], reached_["reconstructed"]);
}
