// The side files of an output (files/SideFiles.hpp) are recognised by their exact form, in the
// output's own directory, and nothing else is: a file that only resembles one is the user's.
#include <gtest/gtest.h>

#include <filesystem>

#include "files/SideFiles.hpp"
#include "tests/h5/ScratchDir.hpp"

using granwave::files::isCheckpointCopyOf;
using granwave::files::isTemporaryOf;
using granwave::files::sideFileKind;
using granwave::testing::ScratchDir;

TEST(SideFiles, EveryFileARunMakesBesideItsOutputIsNamed) {
  const ScratchDir dir;
  const std::string run = dir.file("r.h5");
  EXPECT_STREQ(sideFileKind(dir.file("r.h5.lock"), run), "lock file");
  EXPECT_STREQ(sideFileKind(dir.file("r.h5.checkpoint"), run), "checkpoint");
  EXPECT_STREQ(sideFileKind(dir.file("r.h5.checkpoint-17.h5md"), run), "checkpoint copy");
  EXPECT_STREQ(sideFileKind(dir.file("r.h5.interrupted"), run), "partial run file");
  EXPECT_STREQ(sideFileKind(dir.file("r.h5.tmp-999999"), run), "temporary");
  EXPECT_STREQ(sideFileKind(dir.file("r.h5.checkpoint-3.h5md.tmp-42"), run), "temporary");
}

TEST(SideFiles, SameNameReachedByAnotherPathIsStillASideFile) {
  const ScratchDir dir;
  std::filesystem::create_directory(dir.file("sub"));
  std::filesystem::create_directory_symlink(dir.file("sub"), dir.file("link"));
  EXPECT_STREQ(sideFileKind(dir.file("link/r.h5.lock"), dir.file("sub/./r.h5")), "lock file");
  EXPECT_STREQ(sideFileKind(dir.file("sub/../sub/r.h5.lock"), dir.file("sub/r.h5")), "lock file");
}

TEST(SideFiles, FilesThatOnlyResembleSideFilesAreNone) {
  const ScratchDir dir;
  const std::string run = dir.file("r.h5");
  std::filesystem::create_directory(dir.file("other"));
  for (const std::string name :
       {"r.h5", "r.h5x.tmp-12", "r.h5.tmp-", "r.h5.tmp-12x", "r.h5.lock2", "r.h5.checkpoint-.h5md",
        "r.h5.checkpoint-notes.txt", "r.h5.checkpoint-2.h5md.bak", "r.h5.interrupted.txt",
        "other/r.h5.lock", "q.h5.lock"})
    EXPECT_EQ(sideFileKind(dir.file(name), run), nullptr) << name;
}

TEST(SideFiles, TemporaryAndCheckpointCopyNamesAreParsedExactly) {
  long pid = 0;
  EXPECT_TRUE(isTemporaryOf("run.h5.tmp-123", "run.h5", pid));
  EXPECT_EQ(pid, 123);
  EXPECT_TRUE(isTemporaryOf("run.fields.h5.tmp-7", "run", pid));
  EXPECT_EQ(pid, 7);
  EXPECT_FALSE(isTemporaryOf("runx.h5.tmp-7", "run", pid));
  EXPECT_FALSE(isTemporaryOf("run.h5.tmp-99999999999999999999", "run.h5", pid));
  EXPECT_TRUE(isCheckpointCopyOf("run.h5.checkpoint-4.h5md", "run.h5"));
  EXPECT_FALSE(isCheckpointCopyOf("run.h5.checkpoint-4.h5md.tmp-9", "run.h5"));
  EXPECT_FALSE(isCheckpointCopyOf("run.h5.checkpoint-x.h5md", "run.h5"));
}
