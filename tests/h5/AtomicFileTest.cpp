// h5::AtomicFile: the file appears at its target only on commit; otherwise (destroyed
// early, exception) nothing is left, not even the temporary.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "h5/AtomicFile.hpp"
#include "h5/H5Error.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave::h5 {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

void writeSomething(File& file) {
  file.writeDataset<double>("/values", {1, 2, 3}, {3});
  file.writeStringAttribute("/values", "unit", "m");
}

TEST(AtomicFile, CommitPublishesAtTargetAndRemovesTemporary) {
  testing::ScratchDir dir;
  const std::string target = dir.file("RUN.h5");
  {
    AtomicFile atomic(target);
    EXPECT_EQ(atomic.temporaryPath().rfind(target + ".tmp-", 0), 0u);
    EXPECT_TRUE(fs::exists(atomic.temporaryPath()));
    writeSomething(atomic.file());
    EXPECT_FALSE(fs::exists(target)) << "visible before commit";
    atomic.commit();
    EXPECT_TRUE(atomic.committed());
    EXPECT_FALSE(fs::exists(atomic.temporaryPath()));
  }
  EXPECT_TRUE(fs::exists(target));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
  const File file = File::openReadOnly(target);
  EXPECT_EQ(file.readDataset<double>("/values"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(file.readStringAttribute("/values", "unit"), "m");
}

TEST(AtomicFile, WithoutCommitLeavesNothing) {
  testing::ScratchDir dir;
  const std::string target = dir.file("RUN.h5");
  {
    AtomicFile atomic(target);
    writeSomething(atomic.file());
    atomic.file().flush();
  }
  EXPECT_TRUE(dir.empty());
}

TEST(AtomicFile, ExceptionDuringWriteLeavesNothing) {
  testing::ScratchDir dir;
  const std::string target = dir.file("RUN.h5");
  EXPECT_THROW(
      {
        AtomicFile atomic(target);
        ExtendibleDataset<double> series = atomic.file().createExtendible<double>("/s", {3}, 8);
        series.append(std::vector<double>{1, 2, 3});
        throw std::runtime_error("simulation failed");
      },
      std::runtime_error);
  EXPECT_TRUE(dir.empty());
}

TEST(AtomicFile, CommitToAnotherPathLeavesTargetUntouched) {
  testing::ScratchDir dir;
  const std::string target = dir.file("RUN.h5");
  {
    AtomicFile atomic(target);
    writeSomething(atomic.file());
    atomic.commitTo(target + ".interrupted");
  }
  EXPECT_FALSE(fs::exists(target));
  EXPECT_TRUE(fs::exists(target + ".interrupted"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

TEST(AtomicFile, ReplacesAnOldTargetOnlyOnCommit) {
  testing::ScratchDir dir;
  const std::string target = dir.file("RUN.h5");
  std::ofstream(target) << "old";
  {
    AtomicFile atomic(target);
    writeSomething(atomic.file());
  }
  EXPECT_EQ(fs::file_size(target), 3u) << "an abandoned write must not touch the old file";
  {
    AtomicFile atomic(target);
    writeSomething(atomic.file());
    atomic.commit();
  }
  EXPECT_EQ(File::openReadOnly(target).readDataset<double>("/values").size(), 3u);
}

TEST(AtomicFile, ErrorsNameTheTargetNotTheTemporary) {
  testing::ScratchDir dir;
  const std::string target = dir.file("RUN.h5");
  AtomicFile atomic(target);
  try {
    atomic.file().readDataset<double>("/missing");
    FAIL() << "no H5Error";
  } catch (const H5Error& error) {
    EXPECT_EQ(std::string(error.what()), target + ": no dataset /missing");
  }
}

TEST(AtomicFile, DeviceOrDirectoryTargetIsRefusedAndStaysAsItWas) {
  testing::ScratchDir dir;
  for (const std::string& target : {std::string("/dev/null"), dir.path().string()}) {
    try {
      AtomicFile atomic(target);
      FAIL() << "no H5Error for " << target;
    } catch (const H5Error& error) {
      EXPECT_THAT(error.what(), HasSubstr(target + ": is a"));
    }
  }
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
  EXPECT_TRUE(dir.empty());
}

TEST(AtomicFile, MissingDirectoryIsAnErrorAndLeavesNothing) {
  testing::ScratchDir dir;
  const std::string target = dir.file("absent/RUN.h5");
  try {
    AtomicFile atomic(target);
    FAIL() << "no H5Error";
  } catch (const H5Error& error) {
    EXPECT_THAT(error.what(), HasSubstr(target + ": its directory"));
    EXPECT_THAT(error.what(), Not(HasSubstr("\n")));
  }
  EXPECT_TRUE(dir.empty());
}

}  // namespace
}  // namespace granwave::h5
