// Outputs are replaced whole or not at all: text files through a temporary and a rename, WAV files
// through juce::TemporaryFile. A failed or killed run leaves the old file and no temporary behind.
#include <gtest/gtest.h>

#include "cli/CliSupport.h"

#include <filesystem>
#include <vector>

#include "cli/WavWriter.h"
#include "core/config/AtomicFile.h"
#include "core/config/ConfigError.h"
#include "core/config/TempFiles.h"

namespace ROSIN_FILE_LOCAL
{
namespace fs = std::filesystem;
using rosin::test::cli::quote;
using rosin::test::cli::slurp;

std::vector<std::string> entries(const std::string& folder)
{
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(folder))
        names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

void writeSomeSamples(rosin::cli::WavWriter& wav)
{
    std::vector<float> samples(4800, 0.25f);
    const float* channels[] = {samples.data()};
    wav.write(channels, static_cast<int>(samples.size()));
}

TEST(AtomicOutput, TextReplacesTheFileWholeAndFailsWithoutTrace)
{
    rosin::test::TempDir dir;
    const std::string file = dir.path() + "/out.json";
    rosin::config::writeFileAtomically(file, "old\n");
    rosin::config::writeFileAtomically(file, "new\n");
    EXPECT_EQ(slurp(file), "new\n");
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out.json"});
    try
    {
        rosin::config::writeFileAtomically(dir.path() + "/no-such-folder/out.json", "x");
        FAIL() << "a file in a missing folder was written";
    }
    catch (const rosin::config::ConfigError& e)
    {
        EXPECT_NE(std::string(e.what()).find("no-such-folder/out.json"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("a writable file"), std::string::npos) << e.what();
    }
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out.json"});
}

TEST(AtomicOutput, AWavFileAppearsOnlyWhenFinished)
{
    rosin::test::TempDir dir;
    const std::string file = dir.path() + "/take.wav";
    rosin::config::writeFileAtomically(file, "the previous take");
    {
        rosin::cli::WavWriter wav(file, 48000.0, 1);
        writeSomeSamples(wav);
        EXPECT_EQ(slurp(file), "the previous take"); // still the old file while writing
    }                                                // destroyed without close(): a render that failed
    EXPECT_EQ(slurp(file), "the previous take");
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"take.wav"});

    rosin::cli::WavWriter wav(file, 48000.0, 1);
    writeSomeSamples(wav);
    wav.close();
    const std::string written = slurp(file);
    EXPECT_EQ(written.substr(0, 4), "RIFF");
    EXPECT_GT(written.size(), 4800u * 4u);
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"take.wav"});
}

// The whole program, killed (SIGKILL) in the middle of a render over an earlier take: the earlier take stays.
TEST(AtomicOutput, KilledRenderLeavesTheEarlierTake)
{
    rosin::test::TempDir dir;
    const std::string take = dir.path() + "/take.wav";
    rosin::config::writeFileAtomically(take, "the previous take");
    const std::string render = "ROSIN_PRESET_DIR=" + quote(ROSIN_SOURCE_PRESET_DIR) + " " +
                               quote(ROSIN_BINARY) + " render --gesture 'steady:seconds=600' --out " +
                               quote(take);
    const std::string script = "cd " + quote(dir.path()) + " && { " + render +
                               " >/dev/null 2>&1 & pid=$!; sleep 1; kill -KILL $pid; wait $pid; }";
    const int raw = std::system(("bash -c " + quote(script)).c_str());
    ASSERT_TRUE(WIFEXITED(raw));
    EXPECT_EQ(WEXITSTATUS(raw), 128 + 9) << "the render was not running when it was killed";
    EXPECT_EQ(slurp(take), "the previous take");
}

} // namespace ROSIN_FILE_LOCAL
