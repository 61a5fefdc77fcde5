// The rules every output follows (files/OutputPath.hpp): devices, FIFOs and directories are
// refused as outputs and as inputs, and an output that is the same file as an input or another
// output is found whether it exists (device and inode) or not (normalised path).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "files/OutputPath.hpp"
#include "tests/h5/ScratchDir.hpp"

using granwave::files::NamedPath;
using granwave::files::PathError;
using granwave::files::requireDistinct;
using granwave::files::requireInputFile;
using granwave::files::requireOutputPath;
using granwave::files::sameFile;
using granwave::testing::ScratchDir;

namespace {

std::string touch(const ScratchDir& dir, const std::string& name) {
  std::ofstream(dir.file(name)) << "x\n";
  return dir.file(name);
}

// The message of the PathError `f` throws, or "" if it throws none.
template <typename F>
std::string refusal(F f) {
  try {
    f();
  } catch (const PathError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(OutputPath, RegularFilesAndNewNamesInExistingDirectoriesAreAccepted) {
  ScratchDir dir;
  EXPECT_NO_THROW(requireOutputPath(touch(dir, "old.h5")));
  EXPECT_NO_THROW(requireOutputPath(dir.file("new.h5")));
}

TEST(OutputPath, DevicesAndDirectoriesAreRefusedAsOutputs) {
  for (const char* path : {"/dev/null", "/dev/full"})
    EXPECT_NE(refusal([&] { requireOutputPath(path); }).find("character device"), std::string::npos)
        << path;
  for (const char* path : {"/", ".", "..", "somewhere/."})
    EXPECT_NE(refusal([&] { requireOutputPath(path); }).find("directory"), std::string::npos)
        << path;
}

TEST(OutputPath, NewNameInMissingDirectoryIsRefusedNamingTheDirectory) {
  ScratchDir dir;
  const std::string message = refusal([&] { requireOutputPath(dir.file("nosuch/run.h5")); });
  EXPECT_NE(message.find("nosuch does not exist"), std::string::npos) << message;
}

TEST(OutputPath, FifoIsRefusedAsInputAndAsOutput) {
  ScratchDir dir;
  const std::string fifo = dir.file("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(refusal([&] { requireInputFile(fifo); }).find("a FIFO"), std::string::npos);
  EXPECT_NE(refusal([&] { requireOutputPath(fifo); }).find("a FIFO"), std::string::npos);
  EXPECT_NE(refusal([&] { requireInputFile("/dev/zero"); }).find("device"), std::string::npos);
  EXPECT_NE(refusal([&] { requireInputFile(dir.file("missing")); }).find("missing"),
            std::string::npos);
}

TEST(OutputPath, SameFileIsFoundThroughHardLinksSymlinksAndUnnormalisedPaths) {
  ScratchDir dir;
  const std::string a = touch(dir, "a.h5");
  std::filesystem::create_hard_link(a, dir.file("hard.h5"));
  std::filesystem::create_symlink(a, dir.file("soft.h5"));
  EXPECT_TRUE(sameFile(a, dir.file("hard.h5")));
  EXPECT_TRUE(sameFile(a, dir.file("soft.h5")));
  EXPECT_TRUE(sameFile(dir.file("new.h5"), dir.file("sub/../new.h5")));
  EXPECT_FALSE(sameFile(a, dir.file("b.h5")));
  EXPECT_FALSE(sameFile(dir.file("x.h5"), dir.file("y.h5")));
}

TEST(OutputPath, OutputOverAnInputOrAnotherOutputIsRefusedNamingBoth) {
  ScratchDir dir;
  const std::string scene = touch(dir, "s.toml");
  const std::string clash = refusal([&] {
    requireDistinct({{"scene", scene}}, {{"run file", dir.file("./s.toml")}});
  });
  EXPECT_NE(clash.find("the run file would overwrite the scene"), std::string::npos) << clash;
  const std::string twice = refusal([&] {
    requireDistinct({{"scene", scene}},
                    {{"fields file", dir.file("f.xdmf")}, {"fields sidecar", dir.file("f.xdmf")}});
  });
  EXPECT_NE(twice.find("would be the same file"), std::string::npos) << twice;
  EXPECT_NO_THROW(requireDistinct({{"scene", scene}, {"again", scene}},
                                  {{"run file", dir.file("r.h5")}, {"fields", dir.file("f.h5")}}));
}

TEST(OutputPath, TemporaryIsBesideTheTargetAndNamedForThisProcess) {
  EXPECT_EQ(granwave::files::temporaryFor("out/run.h5"),
            "out/run.h5.tmp-" + std::to_string(::getpid()));
}

TEST(OutputPath, NameTooLongForTheTemporaryIsRefusedWithItsLength) {
  const ScratchDir dir;
  const std::string message = refusal([&] { requireOutputPath(dir.file(std::string(250, 'n'))); });
  EXPECT_NE(message.find("a file name of 250 characters is too long"), std::string::npos)
      << message;
  EXPECT_LT(message.size(), 200u) << message;
  EXPECT_EQ(refusal([&] { requireOutputPath(dir.file(std::string(200, 'n'))); }), "");
}

TEST(OutputPath, UserNamedFileThatIsASideFileOfAnOutputIsRefused) {
  const ScratchDir dir;
  const std::string scene = touch(dir, "r.h5.lock");
  const std::string message = refusal([&] {
    requireDistinct({{"scene", scene}}, {{"run file", dir.file("r.h5")}});
  });
  EXPECT_NE(message.find("the scene is named like the lock file granwave makes beside the run "
                         "file"),
            std::string::npos)
      << message;
  // The command's own side files, marked derived, are no clash.
  EXPECT_EQ(refusal([&] {
              requireDistinct({}, {{"run file", dir.file("r.h5")},
                                   {"checkpoint", dir.file("r.h5.checkpoint"), true}});
            }),
            "");
}

TEST(OutputPath, OutputDirectoryMustBeADirectoryOrANewName) {
  const ScratchDir dir;
  const std::string file = touch(dir, "afile");
  EXPECT_EQ(refusal([&] { granwave::files::requireOutputDirectory(dir.file("new/deeper"), "-o"); }),
            "");
  EXPECT_NE(refusal([&] {
              granwave::files::requireOutputDirectory(file, "-o");
            }).find("afile: is a regular file; -o must name a directory"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              granwave::files::requireOutputDirectory(file + "/runs", "--cache");
            }).find("afile: is a regular file; --cache"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              granwave::files::requireOutputDirectory("/dev/null", "--cache");
            }).find("is a character device"),
            std::string::npos);
}
