// Helper programs run from an argument vector, never through a shell: hostile names stay names.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lab/scan/ChildProcess.h"

namespace fs = std::filesystem;
using namespace rosin::scan;

TEST(ChildProcess, ExitStatusIsReturned)
{
    EXPECT_EQ(runProgram({"sh", "-c", "exit 3"}), 3);
    EXPECT_EQ(runProgram({"true"}), 0);
    EXPECT_EQ(runProgram({"no-such-program-rosin-test"}), -1);
    EXPECT_EQ(runProgram({}), -1);
}

TEST(ChildProcess, HostileArgumentsReachTheProgramAsOneArgumentAndRunNothing)
{
    const fs::path dir = fs::temp_directory_path() / "rosin-child-process-test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const std::string name : {"r'; touch pwned; echo '", "a b $(touch pwned2)",
                                   "line\nbreak `touch pwned3`", "\"quoted\" && touch pwned4"})
    {
        EXPECT_EQ(runProgram({"touch", (dir / name).string()}, true), 0) << name;
        EXPECT_TRUE(fs::exists(dir / name)) << name; // the literal name, one file
    }
    int files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir))
        ++files;
    EXPECT_EQ(files, 4); // nothing else was created there
    for (const char* p : {"pwned", "pwned2", "pwned3", "pwned4"})
        EXPECT_FALSE(fs::exists(p)) << p; // nor in the working directory
    fs::remove_all(dir);
}

TEST(ChildProcess, ProgramsAreFoundOnPathOrByPath)
{
    EXPECT_TRUE(programAvailable("sh"));
    EXPECT_TRUE(programAvailable("/bin/sh"));
    EXPECT_FALSE(programAvailable("no-such-program-rosin-test"));
    EXPECT_FALSE(programAvailable("/no/such/program"));
}

TEST(ChildProcess, FiguresUseAPythonThatHasMatplotlib)
{
    // .ci/install-deps installs Debian's python3-matplotlib, so one of the candidates has it here; whichever
    // python3 comes first on PATH (this machine's is a pyenv build without it) does not matter.
    EXPECT_NE(figurePythonCandidates().find("/usr/bin/python3"), std::string::npos);
    const std::string& python = figurePython();
    ASSERT_FALSE(python.empty()) << "tried " << figurePythonCandidates();
    EXPECT_EQ(runProgram({python, "-c", "import matplotlib, numpy"}, true), 0);
    EXPECT_EQ(&figurePython(), &python); // looked up once
}
