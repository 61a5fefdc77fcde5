// removeOrphanedTemporaries: temporaries of processes that can no longer write go, those of
// running processes stay.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "studies/runner/OrphanedTemporaries.hpp"

namespace granwave {
namespace {

namespace fs = std::filesystem;

class OrphanedTemporaries : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("granwave-orphans-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string touch(const std::string& name) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << "partial";
    return path;
  }
  std::string run() const { return (dir_ / "particles-0123").string(); }

  fs::path dir_;
};

// A child that exits at once and is not waited for: a zombie until waitpid.
pid_t makeZombie() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  for (int i = 0; i < 500; ++i) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    std::getline(stat, line);
    const std::size_t close = line.rfind(')');
    if (close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'Z') return pid;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return pid;
}

TEST_F(OrphanedTemporaries, TemporaryOfAZombieProcessIsRemoved) {
  // A run killed with its study stays a zombie where PID 1 does not reap (containers).
  const pid_t zombie = makeZombie();
  ASSERT_GT(zombie, 0);
  const std::string tmp = touch("particles-0123.h5.tmp-" + std::to_string(zombie));
  removeOrphanedTemporaries(run());
  EXPECT_FALSE(fs::exists(tmp));
  ::waitpid(zombie, nullptr, 0);
}

TEST_F(OrphanedTemporaries, TemporaryOfAReapedProcessIsRemoved) {
  const pid_t gone = makeZombie();
  ::waitpid(gone, nullptr, 0);
  const std::string tmp = touch("particles-0123.fields.h5.tmp-" + std::to_string(gone));
  removeOrphanedTemporaries(run());
  EXPECT_FALSE(fs::exists(tmp));
}

TEST_F(OrphanedTemporaries, TemporariesOfRunningProcessesAndOtherRunsAreKept) {
  const std::string own = touch("particles-0123.h5.tmp-" + std::to_string(::getpid()));
  const std::string parent = touch("particles-0123.h5.tmp-" + std::to_string(::getppid()));
  const std::string other = touch("particles-9999.h5.tmp-999999999");
  const std::string record = touch("particles-0123.done.tmp");
  removeOrphanedTemporaries(run());
  EXPECT_TRUE(fs::exists(own));
  EXPECT_TRUE(fs::exists(parent));
  EXPECT_TRUE(fs::exists(other));
  EXPECT_TRUE(fs::exists(record));
}

}  // namespace
}  // namespace granwave
