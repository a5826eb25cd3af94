// The grid is found from the trials: distinct values, occupied and missing cells, invalid trials left out.
#include <gtest/gtest.h>

#include "lab/discovery/ScanGrid.h"

namespace rosin::discovery
{
namespace ROSIN_FILE_LOCAL
{

Trial guettler(double beta, double force, double acceleration, bool valid = true)
{
    static int n = 0;
    return Trial{"t" + std::to_string(n++),          "t.wav", beta,         force,
                 ConstantAcceleration{acceleration}, valid,   std::nullopt, std::nullopt};
}

// 3 forces x 4 accelerations at beta 0.0899, listed out of order; cell (1.0 N, 2.0 m/s^2) never measured and
// cell (0.5 N, 0.5 m/s^2) measured only by an invalid trial; one repeat.
std::vector<Trial> guettlerScan()
{
    std::vector<Trial> trials;
    for (double force : {1.5, 0.5, 1.0})
        for (double a : {2.0, 0.5, 1.0, 4.0})
        {
            if (force == 1.0 && a == 2.0)
                continue;
            trials.push_back(guettler(0.0899, force, a, !(force == 0.5 && a == 0.5)));
        }
    trials.push_back(guettler(0.0899, 1.5, 4.0 * (1 + 1e-12))); // a repeat, printed slightly differently
    return trials;
}

TEST(ScanGrid, GuettlerGridWithAnInvalidTrialAndAMissingCell)
{
    const auto trials = guettlerScan();
    const ScanGrid g = findScanGrid(trials);
    EXPECT_EQ(g.kind, ScanKind::Guettler);
    EXPECT_EQ(g.betas, std::vector<double>{0.0899});
    EXPECT_EQ(g.forces, (std::vector<double>{0.5, 1.0, 1.5}));
    EXPECT_EQ(g.motion, (std::vector<double>{0.5, 1.0, 2.0, 4.0}));
    EXPECT_EQ(g.validTrials, 11u);
    EXPECT_EQ(g.invalidTrials, 1u);
    EXPECT_EQ(g.possibleCells(), 12u);
    EXPECT_EQ(g.cells.size(), 10u);

    const auto missing = g.missingCells();
    ASSERT_EQ(missing.size(), 2u);
    EXPECT_EQ(g.forces[missing[0].force], 0.5); // only the invalid trial was there
    EXPECT_EQ(g.motion[missing[0].motion], 0.5);
    EXPECT_EQ(g.forces[missing[1].force], 1.0); // never measured
    EXPECT_EQ(g.motion[missing[1].motion], 2.0);

    EXPECT_EQ(g.find(0.0899, 1.0, 2.0), nullptr);
    EXPECT_EQ(g.find(0.0899, 0.5, 0.5), nullptr);
    EXPECT_EQ(g.find(0.2, 1.0, 1.0), nullptr);
    const GridCell* repeat = g.find(0.0899, 1.5, 4.0);
    ASSERT_NE(repeat, nullptr);
    EXPECT_EQ(repeat->trials.size(), 2u);
    for (std::size_t i : repeat->trials)
        EXPECT_EQ(trials[i].bowForce, 1.5);
    const GridCell* one = g.find(0.0899, 0.5, 1.0);
    ASSERT_NE(one, nullptr);
    ASSERT_EQ(one->trials.size(), 1u);
    EXPECT_EQ(std::get<ConstantAcceleration>(trials[one->trials[0]].gesture).acceleration, 1.0);

    EXPECT_EQ(g.summary(),
              "Guettler scan: 1 beta x 3 forces x 4 accelerations, 10 of 12 cells, 1 invalid trial");
}

TEST(ScanGrid, CellsAreOrderedAndEveryValidTrialIsInOne)
{
    const auto trials = guettlerScan();
    const ScanGrid g = findScanGrid(trials);
    std::size_t counted = 0;
    for (std::size_t c = 0; c < g.cells.size(); ++c)
    {
        counted += g.cells[c].trials.size();
        if (c > 0)
            EXPECT_LT(std::tie(g.cells[c - 1].beta, g.cells[c - 1].force, g.cells[c - 1].motion),
                      std::tie(g.cells[c].beta, g.cells[c].force, g.cells[c].motion));
    }
    EXPECT_EQ(counted, g.validTrials);
}

TEST(ScanGrid, SchellengScanAcrossBetas)
{
    std::vector<Trial> trials;
    for (double beta : {0.05, 0.1})
        for (double force : {0.2, 0.4, 0.8})
            trials.push_back({"s", "s.wav", beta, force, Steady{0.1}, true, std::nullopt, std::nullopt});
    const ScanGrid g = findScanGrid(trials);
    EXPECT_EQ(g.kind, ScanKind::Schelleng);
    EXPECT_EQ(g.motion, std::vector<double>{0.1});
    EXPECT_EQ(g.cells.size(), 6u);
    EXPECT_TRUE(g.missingCells().empty());
    EXPECT_EQ(g.summary(), "Schelleng scan: 2 betas x 3 forces x 1 speed, 6 of 6 cells, 0 invalid trials");
}

TEST(ScanGrid, MixedRecordedAndEmpty)
{
    std::vector<Trial> trials{guettler(0.1, 1.0, 1.0)};
    trials.push_back({"r", "r.wav", 0.1, 2.0, Recorded{}, true, std::nullopt, std::nullopt});
    const ScanGrid mixed = findScanGrid(trials);
    EXPECT_EQ(mixed.kind, ScanKind::Mixed);
    EXPECT_TRUE(mixed.motion.empty());
    EXPECT_EQ(mixed.cells.size(), 2u);
    EXPECT_NE(mixed.find(0.1, 2.0), nullptr);

    trials[0].valid = false; // an invalid trial does not decide the kind
    EXPECT_EQ(findScanGrid(trials).kind, ScanKind::Recorded);

    trials[1].valid = false;
    const ScanGrid empty = findScanGrid(trials);
    EXPECT_EQ(empty.kind, ScanKind::Empty);
    EXPECT_TRUE(empty.cells.empty());
    EXPECT_TRUE(empty.missingCells().empty());
    EXPECT_EQ(empty.invalidTrials, 2u);
    EXPECT_EQ(findScanGrid(std::vector<Trial>{}).kind, ScanKind::Empty);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::discovery
