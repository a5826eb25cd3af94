// `rosin discover` through the built binary on small datasets made in the test by `rosin synth-data` (6 x 6
// Guettler grid at one beta, 0.3 s trials); the only channel between generator and workflow is the dataset
// folder. A hidden junction growth (or sticking creep) is named first and most of the gap goes; a dataset
// with nothing hidden names nothing; a malformed dataset is refused with a message naming the file and field.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "config/TempFiles.h"

namespace
{
namespace fs = std::filesystem;

struct Result
{
    int status = -1;
    std::string out, err;
};

std::string quote(const std::string& arg)
{
    std::string q = "'";
    for (char c : arg)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string slurp(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class DiscoverCli : public ::testing::Test
{
  protected:
    Result rosin(const std::vector<std::string>& args)
    {
        std::string command = "cd " + quote(dir.path()) +
                              " && ROSIN_PRESET_DIR=" + quote(ROSIN_SOURCE_PRESET_DIR) + " " +
                              quote(ROSIN_BINARY);
        for (const auto& a : args)
            command += " " + quote(a);
        command += " >" + quote(dir.path() + "/stdout.txt") + " 2>" + quote(dir.path() + "/stderr.txt");
        const int raw = std::system(command.c_str());
        return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir.path() + "/stdout.txt"),
                slurp(dir.path() + "/stderr.txt")};
    }
    // A 6 x 6 Guettler dataset of 0.3 s trials at beta 0.0899 with `effect` hidden.
    void makeDataset(const std::string& effect, const std::string& seed, const std::string& out)
    {
        const Result r =
            rosin({"synth-data", "--effect", effect, "--scan", "guettler", "--grid", "6", "--beta", "0.0899",
                   "--duration", "0.3", "--seed", seed, "--threads", "2", "--out", out});
        ASSERT_EQ(r.status, 0) << r.err;
    }
    nlohmann::json discover(const std::string& dataset)
    {
        const Result r = rosin({"discover", dataset, "--json", dataset + ".json", "--report",
                                dataset + "-report", "--threads", "2"});
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_TRUE(fs::exists(path(dataset + "-report/report.md")));
        return nlohmann::json::parse(slurp(path(dataset + ".json")));
    }
    std::string path(const std::string& name) const { return dir.path() + "/" + name; }

    rosin::test::TempDir dir;
};

TEST_F(DiscoverCli, HiddenJunctionGrowthIsNamedFirstAndHalvesTheGap)
{
    makeDataset("junction-growth:growth=0.3,onsetTime=0.003", "3", "jg");
    const auto j = discover("jg");
    EXPECT_EQ(j["status"], "effect-found");
    ASSERT_FALSE(j["steps"].empty());
    EXPECT_EQ(j["steps"][0]["effect"], "junction-growth");
    EXPECT_GT(j["gapBefore"].get<double>(), 1.0);
    EXPECT_LE(j["gapAfter"].get<double>(), 0.5 * j["gapBefore"].get<double>());
    EXPECT_EQ(j["trialsUsed"].get<int>() + j["trialsSkipped"].get<int>(), 36);
    EXPECT_GE(j["trialsSkipped"].get<int>(), 1);
    EXPECT_LT(j["steps"][0]["pValue"].get<double>(), 0.01);
    EXPECT_GE(j["steps"][0]["heldOutGain"].get<double>(), 0.2);
}

TEST_F(DiscoverCli, HiddenStickingCreepIsNamedFirstAndHalvesTheGap)
{
    makeDataset("sticking-creep:creepResistance=60", "5", "sc");
    const auto j = discover("sc");
    EXPECT_EQ(j["status"], "effect-found");
    ASSERT_FALSE(j["steps"].empty());
    EXPECT_EQ(j["steps"][0]["effect"], "sticking-creep");
    EXPECT_LE(j["gapAfter"].get<double>(), 0.5 * j["gapBefore"].get<double>());
    // The fitted dashpot is the hidden one within a factor 1.5.
    const double eta = j["steps"][0]["parameters"]["creepResistance"].get<double>();
    EXPECT_GT(eta, 40.0);
    EXPECT_LT(eta, 90.0);
}

TEST_F(DiscoverCli, NothingHiddenNamesNothing)
{
    makeDataset("none", "4", "none");
    const auto j = discover("none");
    EXPECT_EQ(j["status"], "no-significant-discrepancy");
    EXPECT_TRUE(j["steps"].empty());
    EXPECT_NEAR(j["gapAfter"].get<double>(), j["gapBefore"].get<double>(), 1e-12);
}

TEST_F(DiscoverCli, MalformedDatasetIsRefusedWithFileAndField)
{
    fs::create_directories(path("bad/trials"));
    nlohmann::json d = {
        {"format", "rosin-measurements/1"},
        {"channels", {{{"name", "bridgeForce"}, {"unit", "N"}}}},
        {"rig", {{"string", {{"tension", 111.0}, {"massPerLength", 0.0027}, {"length", 0.69}}}}},
        {"trials", nlohmann::json::array()}};
    std::ofstream(path("bad/dataset.json")) << d.dump(1);
    const Result r = rosin({"discover", "bad", "--json", "bad.json", "--report", "bad-report"});
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("dataset.json"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("sampleRate"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("bad.json")));
}

TEST_F(DiscoverCli, MissingDatasetArgumentIsAUsageError)
{
    const Result r = rosin({"discover", "--json", "x.json", "--report", "x"});
    EXPECT_EQ(r.status, 2) << r.err;
}

} // namespace
