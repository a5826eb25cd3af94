// Trial files stay inside the dataset folder: no absolute paths, no "..", no way out through a symbolic link.
#include <gtest/gtest.h>

#include <filesystem>

#include "lab/discovery/DatasetFixtures.h"
#include "lab/discovery/DatasetReader.h"
#include "lab/discovery/TrialPath.h"

namespace rosin::discovery
{
namespace ROSIN_FILE_LOCAL
{

namespace fs = std::filesystem;

TEST(TrialPath, PathsInsideTheFolderAreFine)
{
    test::DatasetFolder folder;
    for (const char* file : {"a.wav", "trials/a.wav", "./trials/a.wav", "trials/x/../a.wav", "trials//a.wav"})
        EXPECT_FALSE(trialFileProblem(folder.path(), file)) << file;
}

TEST(TrialPath, PathsOutsideTheFolderAreNamed)
{
    test::DatasetFolder folder;
    EXPECT_EQ(trialFileProblem(folder.path(), "/tmp/a.wav"), "an absolute path");
    EXPECT_EQ(trialFileProblem(folder.path(), ""), "an empty path");
    EXPECT_EQ(trialFileProblem(folder.path(), "../a.wav"), "a path that leaves the dataset folder");
    EXPECT_EQ(trialFileProblem(folder.path(), "trials/../../a.wav"), "a path that leaves the dataset folder");
    EXPECT_EQ(trialFileProblem(folder.path(), "."), "a path that leaves the dataset folder");
    EXPECT_EQ(trialFileProblem(folder.path(), "trials/"), "a folder, not a file");
}

TEST(TrialPath, SymbolicLinksOutOfTheFolderAreRejected)
{
    test::DatasetFolder folder, elsewhere;
    fs::create_directory_symlink(elsewhere.path(), fs::path(folder.path()) / "trials");
    fs::create_symlink(fs::path(elsewhere.path()) / "x.wav", fs::path(folder.path()) / "link.wav");
    const auto viaFolder = trialFileProblem(folder.path(), "trials/a.wav");
    ASSERT_TRUE(viaFolder);
    EXPECT_NE(viaFolder->find("through a symbolic link"), std::string::npos) << *viaFolder;
    EXPECT_TRUE(trialFileProblem(folder.path(), "link.wav")); // dangling: a writer would create x.wav outside
    fs::create_directory_symlink(fs::path(elsewhere.path()) / "missing", fs::path(folder.path()) / "gone");
    EXPECT_TRUE(trialFileProblem(folder.path(), "gone/deeper/x.wav"));

    auto j = test::specExample(); // its trial is trials/b0899-f03-a10.wav, now outside
    folder.describe(j);
    try
    {
        readDatasetDescription(folder.path());
        FAIL() << "accepted a trial file behind a symbolic link";
    }
    catch (const DatasetError& e)
    {
        EXPECT_EQ(e.field(), "trials[0].file");
        EXPECT_NE(std::string(e.what()).find("symbolic link"), std::string::npos) << e.what();
    }
}

TEST(TrialPath, SymbolicLinksInsideTheFolderAreFine)
{
    test::DatasetFolder folder;
    fs::create_directory(fs::path(folder.path()) / "raw");
    fs::create_directory_symlink("raw", fs::path(folder.path()) / "trials");
    EXPECT_FALSE(trialFileProblem(folder.path(), "trials/a.wav"));
}

TEST(TrialPath, AFolderReachedThroughASymbolicLinkIsItself)
{
    // The dataset folder may itself be a link: only links that lead out of it matter.
    test::DatasetFolder real, parent;
    const fs::path link = fs::path(parent.path()) / "dataset";
    fs::create_directory_symlink(real.path(), link);
    EXPECT_FALSE(trialFileProblem(link, "trials/a.wav"));
}

TEST(TrialPath, ResolvesRelativeToTheFolder)
{
    test::DatasetFolder folder;
    folder.describe(std::string(test::kSpecExample));
    const Dataset d = readDatasetDescription(folder.path());
    EXPECT_EQ(trialFilePath(d, d.trials[0]), fs::path(folder.path()) / "trials/b0899-f03-a10.wav");
    Trial outside = d.trials[0];
    outside.file = "../x.wav";
    EXPECT_THROW(trialFilePath(d, outside), DatasetError);
}

} // namespace ROSIN_FILE_LOCAL
} // namespace rosin::discovery
