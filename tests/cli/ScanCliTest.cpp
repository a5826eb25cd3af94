// `rosin scan` through the built binary: help, bad input (clear message, exit status, nothing written), a
// tiny scan, shards + merge and MPI against a single run (byte for byte), Ctrl-C and resume, missing figure
// script.
#include <gtest/gtest.h>

#include "cli/CliSupport.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>

#include "core/config/TempFiles.h"

namespace ROSIN_FILE_LOCAL
{
namespace fs = std::filesystem;

using rosin::test::cli::quote;
using rosin::test::cli::Result;
using rosin::test::cli::slurp;

class ScanCli : public ::testing::Test
{
  protected:
    // Runs `PREFIX rosin scan ARGS` in the scratch folder; `prefix` may set variables or wrap the command.
    Result scan(const std::vector<std::string>& args, const std::string& prefix = "")
    {
        std::string command = "cd " + quote(dir.path()) +
                              " && ROSIN_PRESET_DIR=" + quote(ROSIN_SOURCE_PRESET_DIR) + " " + prefix + " " +
                              quote(ROSIN_BINARY) + " scan";
        for (const auto& a : args)
            command += " " + quote(a);
        command += " >" + quote(dir.path() + "/stdout.txt") + " 2>" + quote(dir.path() + "/stderr.txt");
        const int raw = std::system(command.c_str());
        return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir.path() + "/stdout.txt"),
                slurp(dir.path() + "/stderr.txt")};
    }
    /// Starts the scan in the background and sends SIGINT once its partial file holds a finished cell, so
    /// the interrupt lands mid-scan however loaded the machine is.
    Result scanInterruptedMidway(const std::vector<std::string>& args, const std::string& outDir)
    {
        return scanSignalled(args, outDir, 2, "INT", 0.0);
    }
    /// Starts the scan in the background, waits until its partial file holds `lines` lines (header included)
    /// or the scan ends, sleeps `seconds` more and sends `signal` (INT, KILL).
    Result scanSignalled(const std::vector<std::string>& args, const std::string& outDir, std::size_t lines,
                         const std::string& signal, double seconds)
    {
        std::string run =
            "ROSIN_PRESET_DIR=" + quote(ROSIN_SOURCE_PRESET_DIR) + " " + quote(ROSIN_BINARY) + " scan";
        for (const auto& a : args)
            run += " " + quote(a);
        const std::string partial = quote(dir.path() + "/" + outDir + "/scan.partial.csv");
        const std::string script =
            "cd " + quote(dir.path()) + " && { " + run + " >" + quote(dir.path() + "/stdout.txt") + " 2>" +
            quote(dir.path() + "/stderr.txt") + " & pid=$!; while kill -0 $pid 2>/dev/null && [ \"$(cat " +
            partial + " 2>/dev/null | wc -l)\" -lt " + std::to_string(lines) +
            " ]; do sleep 0.002; done; sleep " + std::to_string(seconds) + "; kill -" + signal +
            " $pid 2>/dev/null; wait $pid; }";
        const int raw = std::system(("bash -c " + quote(script)).c_str());
        return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir.path() + "/stdout.txt"),
                slurp(dir.path() + "/stderr.txt")};
    }
    std::string path(const std::string& name) const { return dir.path() + "/" + name; }
    bool sameFiles(const std::string& a, const std::string& b) const
    {
        for (const char* f : {"/scan.csv", "/scan.json"})
            if (slurp(path(a) + f) != slurp(path(b) + f) || slurp(path(a) + f).empty())
                return false;
        return true;
    }

    rosin::test::TempDir dir;
};

// A tiny Guettler scan: one beta, 3 x 3 cells of 0.1 s.
std::vector<std::string> tiny(const std::string& out, std::vector<std::string> more = {})
{
    std::vector<std::string> args = {"guettler", "--grid",       "3",     "--beta", "0.0899", "--duration",
                                     "0.1",      "--no-figures", "--out", out};
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

TEST_F(ScanCli, HelpDocumentsTheOptions)
{
    const Result r = scan({"--help"});
    EXPECT_EQ(r.status, 0);
    for (const char* text : {"--preset",
                             "--friction",
                             "--beta",
                             "--grid",
                             "--force-range",
                             "--acceleration-range",
                             "--bow-speed",
                             "--beta-range",
                             "--duration",
                             "--sample-rate",
                             "--threads",
                             "--shard",
                             "--mpi",
                             "--out",
                             "--no-figures",
                             "--layer-thickness",
                             "--contact-radius",
                             "--contact coulomb|hertz",
                             "--finger-damping",
                             "--rigid-bridge",
                             "--no-torsion",
                             "--no-stiffness",
                             "rosin scan merge DIR",
                             "scan.partial.csv"})
        EXPECT_NE(r.out.find(text), std::string::npos) << text;
}

TEST_F(ScanCli, BadValuesNameTheOptionAndWriteNothing)
{
    struct Case
    {
        std::vector<std::string> more;
        const char* message;
    };
    for (const Case& c : {Case{{"--grid", "301"}, "--grid: expected N or NxM"},
                          Case{{"--grid", "20x400"}, "but got \"20x400\""},
                          Case{{"--friction", "plasticc"}, "--friction: expected one of classical"},
                          Case{{"--beta", "0.9"}, "--beta: expected comma-separated betas"},
                          Case{{"--force-range", "3:1"}, "--force-range: expected FIRST:LAST"},
                          Case{{"--acceleration-range", "0.1"}, "--acceleration-range: expected FIRST:LAST"},
                          Case{{"--shard", "2/2"}, "--shard: expected K/N"},
                          Case{{"--threads", "0"}, "--threads: expected an integer in 1..4096"},
                          Case{{"--duration", "-1"}, "--duration: expected a number > 0"},
                          Case{{"--sample-rate", "44100.5"}, "--sample-rate"},
                          Case{{"--contact", "elastic"}, "--contact: expected one of coulomb, hertz"},
                          Case{{"--preset", "no-such-preset"}, "no-such-preset"}})
    {
        const Result r = scan(tiny("never", c.more));
        EXPECT_EQ(r.status, 1) << c.message;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(path("never"))) << c.message;
    }
}

TEST_F(ScanCli, UsageErrorsExitWithTwo)
{
    EXPECT_EQ(scan({}).status, 2);
    EXPECT_EQ(scan({"schellen", "--out", "x"}).status, 2);
    EXPECT_EQ(scan({"guettler", "--grid", "3"}).status, 2); // no --out
    EXPECT_EQ(scan(tiny("x", {"--bogus"})).status, 2);
    const Result wrongKind = scan(tiny("x", {"--bow-speed", "0.1"}));
    EXPECT_EQ(wrongKind.status, 2);
    EXPECT_NE(wrongKind.err.find("--bow-speed applies to schelleng scans only"), std::string::npos);
    EXPECT_EQ(scan(tiny("x", {"--shard", "0/2", "--mpi"})).status, 2);
    EXPECT_EQ(scan({"merge"}).status, 2);
    EXPECT_FALSE(fs::exists(path("x")));
    fs::create_directories(path("empty"));
    const Result merge = scan({"merge", path("empty")});
    EXPECT_EQ(merge.status, 1);
    EXPECT_NE(merge.err.find("no shard files"), std::string::npos) << merge.err;
}

TEST_F(ScanCli, TinyScanWritesCsvAndJson)
{
    const Result r = scan(tiny("tiny"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string csv = slurp(path("tiny/scan.csv"));
    EXPECT_EQ(csv.rfind("cell,beta,bowForce,acceleration,regime,transientPeriods,muStatic,jump,firstSlipTime,"
                        "slipsPerPeriod,pitchCents,failure\n0,0.0899,0.4,0.08,",
                        0),
              0u)
        << csv;
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 10);
    const std::string json = slurp(path("tiny/scan.json"));
    for (const char* key : {"\"format\": \"rosin-scan/1\"", "\"kind\": \"guettler\"", "\"helmholtzFraction\"",
                            "\"reachedFraction\"", "\"guettlerWedge\""})
        EXPECT_NE(json.find(key), std::string::npos) << key;
    EXPECT_TRUE(fs::exists(path("tiny/scan.spec.json")));
    EXPECT_FALSE(fs::exists(path("tiny/scan.partial.csv")));
    EXPECT_NE(r.err.find("scan: 9/9 cells"), std::string::npos) << r.err;
}

TEST_F(ScanCli, ShardsMergedEqualASingleRun)
{
    ASSERT_EQ(scan(tiny("single")).status, 0);
    ASSERT_EQ(scan(tiny("sharded", {"--shard", "0/2"})).status, 0);
    const Result early = scan({"merge", path("sharded"), "--no-figures"});
    EXPECT_EQ(early.status, 1);
    EXPECT_NE(early.err.find("missing shard(s) 1 of 2"), std::string::npos) << early.err;
    ASSERT_EQ(scan(tiny("sharded", {"--shard", "1/2"})).status, 0);
    ASSERT_EQ(scan({"merge", path("sharded"), "--no-figures"}).status, 0);
    EXPECT_TRUE(sameFiles("single", "sharded"));
}

TEST_F(ScanCli, MpiRunEqualsASingleRun)
{
#if defined(ROSIN_TEST_MPIEXEC)
    ASSERT_EQ(scan(tiny("single")).status, 0);
    const Result r = scan(tiny("mpi", {"--mpi", "--threads", "1"}),
                          std::string(ROSIN_TEST_MPIEXEC) + " --allow-run-as-root --oversubscribe -np 2");
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_TRUE(sameFiles("single", "mpi"));
#else
    GTEST_SKIP() << "rosin was built without MPI, or mpirun was not found";
#endif
}

// Ctrl-C (SIGINT from timeout(1)) stops the scan with the finished rows kept; the same command resumes and
// gives the files of an uninterrupted run.
TEST_F(ScanCli, InterruptedScanResumes)
{
    const std::vector<std::string> args = {"guettler", "--friction",   "classical", "--beta",
                                           "0.0899",   "--grid",       "10",        "--threads",
                                           "1",        "--no-figures", "--out"};
    auto with = [&](const std::string& out)
    {
        auto a = args;
        a.push_back(out);
        return a;
    };
    const Result stopped = scanInterruptedMidway(with("resumed"), "resumed");
    if (stopped.status == 0)
        GTEST_SKIP() << "the scan finished before the interrupt";
    EXPECT_EQ(stopped.status, 130) << stopped.err;
    EXPECT_NE(stopped.out.find("run the same command again to resume"), std::string::npos) << stopped.out;
    EXPECT_TRUE(fs::exists(path("resumed/scan.partial.csv")));
    const Result resumed = scan(with("resumed"));
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    EXPECT_NE(resumed.out.find("resuming: "), std::string::npos) << resumed.out;
    ASSERT_EQ(scan(with("single")).status, 0);
    EXPECT_TRUE(sameFiles("single", "resumed"));
    EXPECT_FALSE(fs::exists(path("resumed/scan.partial.csv")));
}

// SIGKILL (no handler can run) at random moments, again and again: every cell finished before a kill is still
// there after it, no cut-off row is ever read back, and the last run's files equal an uninterrupted run's.
TEST_F(ScanCli, KilledScanLosesNoFinishedCellAndReadsBackNoTornRow)
{
    const std::vector<std::string> args = {"guettler", "--friction",   "classical", "--beta",
                                           "0.0899",   "--grid",       "16",        "--threads",
                                           "2",        "--no-figures", "--out"};
    auto with = [&](const std::string& out)
    {
        auto a = args;
        a.push_back(out);
        return a;
    };
    std::mt19937 random(20261127);
    std::size_t finishedBefore = 0, kills = 0;
    for (int round = 0; round < 8; ++round)
    {
        const std::size_t wait =
            1 + finishedBefore + std::uniform_int_distribution<std::size_t>(3, 30)(random);
        const double late = std::uniform_real_distribution<double>(0.0, 0.004)(random);
        const Result r = scanSignalled(with("killed"), "killed", wait, "KILL", late);
        if (r.status == 0)
            break; // finished before the kill
        ++kills;
        // Rows the partial file holds whole (newline-terminated) after the kill: none may be lost next time.
        const std::string partial = slurp(path("killed/scan.partial.csv"));
        const std::size_t whole = static_cast<std::size_t>(std::count(partial.begin(), partial.end(), '\n'));
        const std::size_t finished = whole > 0 ? whole - 1 : 0;
        EXPECT_GE(finished, finishedBefore) << "round " << round << ": finished cells were lost";
        finishedBefore = finished;
    }
    EXPECT_GE(kills, 3u) << "the scan finished before most kills; the test did not test much";
    const Result resumed = scan(with("killed"));
    ASSERT_EQ(resumed.status, 0) << resumed.err;
    EXPECT_EQ(resumed.err.find("warning:"), std::string::npos) << resumed.err;
    ASSERT_EQ(scan(with("whole")).status, 0);
    EXPECT_TRUE(sameFiles("whole", "killed"));
    std::printf(
        "[figure] %zu SIGKILLs, %zu cells finished before the last; files equal an uninterrupted run\n",
        kills, finishedBefore);
}

TEST_F(ScanCli, MissingFigureScriptIsAWarning)
{
    auto args = tiny("figures");
    args.erase(std::find(args.begin(), args.end(), "--no-figures"));
    const Result r = scan(args, "ROSIN_FIGURE_SCRIPT=/nonexistent/plot_scan.py");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(
        r.err.find("warning: figures not drawn: the figure script /nonexistent/plot_scan.py is missing"),
        std::string::npos)
        << r.err;
    EXPECT_FALSE(slurp(path("figures/scan.csv")).empty());
    EXPECT_FALSE(slurp(path("figures/scan.json")).empty());
}

// The figure scripts are found relative to the executable: an installed layout (PREFIX/bin/rosin with
// PREFIX/share/rosin/figures) uses its own scripts, and the build tree has its copy beside build/rosin.
TEST_F(ScanCli, FigureScriptsAreFoundBesideTheExecutable)
{
    const fs::path binary(ROSIN_BINARY);
    const fs::path beside = binary.parent_path() / "share/rosin/figures/plot_scan.py";
    EXPECT_EQ(slurp(beside),
              slurp(fs::path(ROSIN_SOURCE_PRESET_DIR).parent_path() / "Source/lab/figures/plot_scan.py"))
        << beside << " is not the source tree's script";

    const fs::path prefix = path("prefix");
    fs::create_directories(prefix / "bin");
    fs::create_directories(prefix / "share/rosin/figures");
    fs::copy_file(binary, prefix / "bin/rosin");
    {
        // A stand-in script that leaves a mark where the real one would draw.
        std::ofstream script(prefix / "share/rosin/figures/plot_scan.py");
        script << "import sys\nopen(sys.argv[1] + '/drawn-by-installed-script', 'w').write('yes')\n";
    }
    auto args = tiny("installed");
    args.erase(std::find(args.begin(), args.end(), "--no-figures"));
    std::string command = "cd " + quote(dir.path()) + " && env -u ROSIN_FIGURE_SCRIPT ROSIN_PRESET_DIR=" +
                          quote(ROSIN_SOURCE_PRESET_DIR) + " " + quote((prefix / "bin/rosin").string()) +
                          " scan";
    for (const auto& a : args)
        command += " " + quote(a);
    ASSERT_EQ(std::system((command + " >/dev/null 2>&1").c_str()), 0);
    EXPECT_EQ(slurp(path("installed/drawn-by-installed-script")), "yes");
}

// No shell injection: the output folder reaches the figure script as one argument, never through a
// shell, so a folder named like a command is only a name.
TEST_F(ScanCli, AnOutputFolderNamedLikeAShellCommandIsOnlyAName)
{
    const std::string evil = "r'; touch pwned; echo '";
    {
        std::ofstream script(path("mark.py"));
        script << "import sys\nopen(sys.argv[1] + '/drawn', 'w').write('yes')\n";
    }
    auto args = tiny(evil);
    args.erase(std::find(args.begin(), args.end(), "--no-figures"));
    const Result r = scan(args, "ROSIN_FIGURE_SCRIPT=" + quote(path("mark.py")));
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(path(evil + "/drawn")), "yes") << r.err;
    EXPECT_FALSE(fs::exists(path("pwned")));
}

TEST_F(ScanCli, CompareDrawsTheDifferenceOfTwoScans)
{
    ASSERT_EQ(scan(tiny("a", {"--friction", "classical"})).status, 0);
    ASSERT_EQ(scan(tiny("b", {"--friction", "plastic"})).status, 0);
    const Result r = scan({"compare", "a", "b", "--out", "diff"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("Helmholtz cells:"), std::string::npos) << r.out;
    // PNG signature: the figure script ran and wrote a real image.
    EXPECT_EQ(slurp(path("diff/compare.png")).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    const Result missing = scan({"compare", "a", "nowhere", "--out", "diff2"});
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.err.find("nowhere/scan.csv: expected a finished scan"), std::string::npos)
        << missing.err;
    EXPECT_EQ(scan({"compare", "a", "--out", "diff3"}).status, 2);
}

} // namespace ROSIN_FILE_LOCAL
