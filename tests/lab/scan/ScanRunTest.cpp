// The run machinery: the same files whether a scan is computed on one thread or several, interrupted and
// resumed, or split into shards and merged; a partial file of another scan is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <sstream>

#include "core/config/TempFiles.h"
#include "core/physics/modal/SimdLevel.h"
#include "lab/scan/CellRunner.h"
#include "lab/scan/CsvRow.h"
#include "lab/scan/Merge.h"
#include "lab/scan/ScanError.h"
#include "lab/scan/SmallScan.h"

using namespace rosin::scan;
namespace fs = std::filesystem;

namespace ROSIN_FILE_LOCAL
{
std::string file(const std::string& dir, const char* name)
{
    return readTextFile(fs::path(dir) / name);
}

// The three files of a complete scan, for byte comparisons.
struct Outputs
{
    std::string csv, json, spec;
    bool operator==(const Outputs&) const = default;
};

Outputs outputs(const std::string& dir)
{
    return {file(dir, "scan.csv"), file(dir, "scan.json"), file(dir, "scan.spec.json")};
}

Outputs reference(const rosin::test::TempDir& tmp)
{
    const std::string dir = tmp.path() + "/single";
    EXPECT_TRUE(test::run(test::smallSpec(), dir, test::quietOptions(1)).complete);
    return outputs(dir);
}

TEST(ScanRun, ThreadCountDoesNotChangeTheFiles)
{
    rosin::test::TempDir tmp;
    const Outputs one = reference(tmp);
    const std::string dir = tmp.path() + "/threads";
    const RunReport r = test::run(test::smallSpec(), dir, test::quietOptions(3));
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.computed, 24u);
    EXPECT_TRUE(outputs(dir) == one);
    EXPECT_FALSE(fs::exists(dir + "/scan.partial.csv"));
    EXPECT_NE(one.csv.find(csvHeader(ScanKind::Guettler) + "\n0,0.0899,0.6,0.5,"), std::string::npos);
}

// A reused runner (reset between cells) gives the same row as a fresh one, whatever ran before.
TEST(ScanRun, CellsDoNotDependOnWhatTheRunnerComputedBefore)
{
    ScanSpec spec = test::smallSpec();
    spec.model.friction = "plastic"; // the thermal law has the most state to reset
    CellRunner fresh(spec), used(spec);
    used.run(23);
    used.run(5);
    EXPECT_EQ(formatRow(used.run(14)), formatRow(fresh.run(14)));
}

// Cells of one beta run together in SIMD lanes: a cell's row must not depend on which cells share its batch.
TEST(ScanRun, CellsDoNotDependOnTheirBatch)
{
    ScanSpec spec = test::smallSpec();
    spec.model.friction = "plastic";
    CellRunner runner(spec);
    const auto together = runner.run(std::vector<std::size_t>{0, 5, 7, 11});
    ASSERT_EQ(together.size(), 4u);
    EXPECT_EQ(formatRow(together[2]), formatRow(runner.run(7)));
    EXPECT_EQ(formatRow(together[0]), formatRow(runner.run(std::vector<std::size_t>{3, 0}).back()));
    EXPECT_THROW(runner.run(std::vector<std::size_t>{0, 12}), std::invalid_argument); // two betas
}

// More cells than lanes, of two betas: each lane takes the next cell as soon as its trial ends (the cells of
// the second beta once all lanes are free), and every cell comes out once, as if it had run alone.
TEST(ScanRun, LanesTakeTheNextCellWhenTheirTrialEnds)
{
    ScanSpec spec = test::smallSpec();
    spec.model.friction = "plastic";
    spec.trialSeconds = 0.25; // long enough for trials to end at different times
    CellRunner streaming(spec), alone(spec);
    std::size_t next = 0;
    std::vector<std::string> rows(spec.cellCount());
    std::vector<std::size_t> order;
    streaming.runAll([&]() -> std::optional<std::size_t>
                     { return next < spec.cellCount() ? std::optional(next++) : std::nullopt; },
                     [&](const CellResult& r)
                     {
                         order.push_back(r.cell);
                         rows[r.cell] = formatRow(r);
                     });
    ASSERT_EQ(order.size(), spec.cellCount());
    EXPECT_FALSE(std::is_sorted(order.begin(), order.end())); // shorter trials ended first
    for (std::size_t c = 0; c < spec.cellCount(); ++c)
        EXPECT_EQ(rows[c], formatRow(alone.run(c))) << "cell " << c;
}

TEST(ScanRun, InterruptedRunResumesToTheSameFiles)
{
    rosin::test::TempDir tmp;
    const Outputs one = reference(tmp);
    const std::string dir = tmp.path() + "/resumed";
    std::atomic<int> polls{0};
    // One thread: cells run in batches of up to eight, so two threads can finish all 24 before the first
    // poll.
    RunOptions stopping = test::quietOptions(1);
    stopping.shouldStop = [&] { return ++polls > 0; }; // "Ctrl-C" at the first poll
    const RunReport first = test::run(test::smallSpec(), dir, stopping);
    EXPECT_FALSE(first.complete);
    EXPECT_GT(first.computed, 0u);
    EXPECT_LT(first.computed, 24u);
    EXPECT_TRUE(fs::exists(dir + "/scan.partial.csv"));
    EXPECT_FALSE(fs::exists(dir + "/scan.csv"));

    const RunReport second = test::run(test::smallSpec(), dir, test::quietOptions(2));
    EXPECT_TRUE(second.complete);
    EXPECT_EQ(second.resumed, first.computed);
    EXPECT_EQ(second.resumed + second.computed, 24u);
    EXPECT_TRUE(outputs(dir) == one);
    EXPECT_FALSE(fs::exists(dir + "/scan.partial.csv"));
    std::printf("[figure] resume: %zu cells before the stop, %zu after; files identical to a single run\n",
                first.computed, second.computed);
}

// Running the same command again on a finished folder (to redraw its figures, say) computes nothing; a
// scan of another specification is computed afresh.
TEST(ScanRun, FinishedRunIsReadBackNotComputedAgain)
{
    rosin::test::TempDir tmp;
    const Outputs one = reference(tmp);
    const std::string dir = tmp.path() + "/single";
    const RunReport again = test::run(test::smallSpec(), dir, test::quietOptions(2));
    EXPECT_TRUE(again.complete);
    EXPECT_EQ(again.computed, 0u);
    EXPECT_EQ(again.resumed, 24u);
    EXPECT_TRUE(outputs(dir) == one);
    EXPECT_FALSE(fs::exists(dir + "/scan.partial.csv"));

    ScanSpec changed = test::smallSpec();
    changed.model.friction = "reconstructed";
    const RunReport other = test::run(changed, dir, test::quietOptions(2));
    EXPECT_EQ(other.computed, 24u);
    EXPECT_NE(file(dir, "scan.spec.json"), one.spec);
    EXPECT_NE(file(dir, "scan.csv"), one.csv);
}

TEST(ScanRun, TornLastLineIsComputedAgain)
{
    rosin::test::TempDir tmp;
    const Outputs one = reference(tmp);
    const std::string dir = tmp.path() + "/torn";
    fs::create_directories(dir);
    const std::string csv = one.csv;
    const std::size_t third = csv.find('\n', csv.find('\n', csv.find('\n') + 1) + 1);
    // The header, two rows and half of the third, as a killed process can leave it.
    writeFileAtomically(dir + "/scan.partial.csv", csv.substr(0, third + 10));
    writeFileAtomically(dir + "/scan.spec.json", one.spec);
    const RunReport r = test::run(test::smallSpec(), dir, test::quietOptions(2));
    EXPECT_EQ(r.resumed, 2u);
    EXPECT_TRUE(outputs(dir) == one);
}

// A finished scan.csv damaged by hand or by a crash of something else: every bad line is named with its line
// number and why, its cell is computed again, and the files come out as an undamaged run's.
TEST(ScanRun, DamagedFinishedScanIsNamedAndItsBadRowsComputedAgain)
{
    rosin::test::TempDir tmp;
    const Outputs one = reference(tmp);
    const std::string dir = tmp.path() + "/single";
    std::vector<std::string> lines;
    std::istringstream in(one.csv);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    ASSERT_EQ(lines.size(), 25u); // header + 24 cells
    auto replaceField = [](std::string row, int field, const std::string& value)
    {
        std::size_t begin = 0;
        for (int f = 0; f < field; ++f)
            begin = row.find(',', begin) + 1;
        return row.replace(begin, row.find(',', begin) - begin, value);
    };
    std::string damaged = lines[0] + "\n";
    damaged += lines[1] + "\n";                         // cell 0 kept
    damaged += replaceField(lines[2], 1, "0.2") + "\n"; // cell 1: beta edited (line 3)
    damaged += replaceField(lines[3], 6, "abc") + "\n"; // cell 2: muStatic not a number (line 4)
    damaged += lines[4] + "\n" + replaceField(lines[4], 10, "1234") + "\n"; // cell 3 twice (lines 5, 6)
    damaged += lines[4] + "\n";          // and its first version again (line 7): still contradicted
    for (std::size_t i = 5; i < 20; ++i) // cells 4..18 kept
        damaged += lines[i] + "\n";
    damaged += lines[20].substr(0, 9); // cut off in cell 19; 20..23 missing
    writeFileAtomically(dir + "/scan.csv", damaged);

    std::ostringstream out, err;
    const RunReport again = runScan(test::smallSpec(), dir, test::quietOptions(2), out, err);
    const std::string warnings = err.str();
    EXPECT_TRUE(again.complete);
    EXPECT_EQ(again.computed, 3u + 1u + 4u); // cells 1, 2, 3; 19 cut off; 20..23 missing
    EXPECT_TRUE(outputs(dir) == one);
    for (const char* expected :
         {"scan.csv: line 3: cell 1 has other coordinates than the grid's",
          "scan.csv: line 4: field muStatic: expected a number but got \"abc\"",
          "scan.csv: line 6: cell 3 appears twice with different results (also line 5)",
          "scan.csv: line 7: cell 3 appears twice with different results (also line 5)",
          "scan.csv: line 23: cut off (no newline at the end of the file)"})
        EXPECT_NE(warnings.find(expected), std::string::npos) << expected << "\n" << warnings;
    EXPECT_NE(warnings.find("; the cell is computed again"), std::string::npos) << warnings;
}

TEST(ScanRun, PartialFileOfAnotherSpecificationIsRefused)
{
    rosin::test::TempDir tmp;
    const std::string dir = tmp.path() + "/other";
    RunOptions stopping = test::quietOptions(1);
    stopping.shouldStop = [] { return true; };
    test::run(test::smallSpec(), dir, stopping);
    ASSERT_TRUE(fs::exists(dir + "/scan.partial.csv"));
    ScanSpec changed = test::smallSpec();
    changed.model.friction = "reconstructed";
    try
    {
        test::run(changed, dir, test::quietOptions(1));
        FAIL() << "a partial file of another scan was accepted";
    }
    catch (const ScanError& e)
    {
        const std::string message = e.what();
        EXPECT_NE(message.find("scan.partial.csv belongs to a different scan specification"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("friction: \"reconstructed\" vs \"classical\""), std::string::npos) << message;
    }
    EXPECT_FALSE(fs::exists(dir + "/scan.csv"));
}

// Files are byte-identical however the work is split only on one vector path, so the spec records the path
// (scan.spec.json "kernels") and a partial run of another path is refused like another specification.
TEST(ScanRun, PartialRunOfAnotherVectorPathIsRefused)
{
    rosin::test::TempDir tmp;
    const std::string dir = tmp.path() + "/path";
    RunOptions stopping = test::quietOptions(1);
    stopping.shouldStop = [] { return true; };
    test::run(test::smallSpec(), dir, stopping);
    std::string spec = file(dir, "scan.spec.json");
    const std::string ours =
        std::string("\"kernels\": \"") + rosin::physics::simdLevelName(rosin::physics::simdLevel()) + "\"";
    ASSERT_NE(spec.find(ours), std::string::npos) << spec;
    spec.replace(spec.find(ours), ours.size(), "\"kernels\": \"another-path\"");
    writeFileAtomically(dir + "/scan.spec.json", spec);
    try
    {
        test::run(test::smallSpec(), dir, test::quietOptions(1));
        FAIL() << "a partial file of another vector path was resumed";
    }
    catch (const ScanError& e)
    {
        EXPECT_NE(std::string(e.what()).find("kernels: \""), std::string::npos) << e.what();
    }
}

TEST(ScanRun, ShardsMergedEqualASingleRun)
{
    rosin::test::TempDir tmp;
    const Outputs one = reference(tmp);
    const std::string dir = tmp.path() + "/shards";
    for (std::size_t k = 0; k < 3; ++k)
    {
        RunOptions o = test::quietOptions(1);
        o.shard = ShardId{k, 3};
        const RunReport r = test::run(test::smallSpec(), dir, o);
        EXPECT_TRUE(r.complete);
        EXPECT_EQ(r.total, 8u);
        EXPECT_TRUE(fs::exists(dir + "/scan.shard-" + std::to_string(k) + "-of-3.csv"));
    }
    EXPECT_FALSE(fs::exists(dir + "/scan.csv"));
    std::ostringstream out, err;
    mergeShards(dir, OutputOptions{false}, out, err);
    EXPECT_TRUE(outputs(dir) == one);
}

TEST(ScanRun, MergeNamesMissingShardsAndRefusesMixedSpecifications)
{
    rosin::test::TempDir tmp;
    const std::string dir = tmp.path() + "/missing";
    RunOptions o = test::quietOptions(1);
    o.shard = ShardId{1, 3};
    test::run(test::smallSpec(), dir, o);
    std::ostringstream out, err;
    try
    {
        mergeShards(dir, OutputOptions{false}, out, err);
        FAIL() << "merged with shards missing";
    }
    catch (const ScanError& e)
    {
        EXPECT_NE(std::string(e.what()).find("missing shard(s) 0, 2 of 3"), std::string::npos) << e.what();
    }
    ScanSpec other = test::smallSpec();
    other.trialSeconds = 0.05;
    for (std::size_t k : {0u, 2u})
    {
        o.shard = ShardId{k, 3};
        test::run(k == 2 ? other : test::smallSpec(), dir, o);
    }
    try
    {
        mergeShards(dir, OutputOptions{false}, out, err);
        FAIL() << "merged shards of two specifications";
    }
    catch (const ScanError& e)
    {
        EXPECT_NE(std::string(e.what()).find("shard 2/3 was computed for a different scan specification"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(dir + "/scan.csv"));
}

} // namespace ROSIN_FILE_LOCAL
