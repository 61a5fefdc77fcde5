#pragma once
// A scratch directory with a short dry scene (s.toml) in which `granwave` runs as a user
// would run it, and the checks every refusal shares (docs/commands.md, "Exit codes").
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace granwave::testing {

struct CliResult {
  int code;
  std::string out, err;
};

inline constexpr const char* kShortDryScene =
    "[contact]\nrestitution = \"dry\"\n[run]\nduration = 0.3\n";

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("granwave_cli_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    write("s.toml", kShortDryScene);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::permissions(dir_, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, ec);
    std::filesystem::remove_all(dir_, ec);
  }

  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
  }
  static std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  std::string read(const std::string& name) const { return slurp(dir_ / name); }
  bool exists(const std::string& name) const { return std::filesystem::exists(dir_ / name); }
  // `prefix` runs before the program in the same shell (ulimit, setpriv); `timeout` turns a
  // command that would block (a FIFO input) into a failure, not a hang. Standard output goes
  // to `out`: out.txt is read back into CliResult::out; another path (/dev/full, to test a
  // full output stream) leaves it empty.
  CliResult run(const std::string& args, const std::string& prefix = "",
                const std::string& out = "out.txt") const {
    const std::string cmd = "cd '" + dir_.string() + "' && " + prefix + " timeout 120 '" +
                            GRANWAVE_BINARY + "' " + args + " > " + out + " 2> err.txt";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "out.txt"),
            slurp(dir_ / "err.txt")};
  }
  // Exit `code` (2 unless told), one line naming `mention`, nothing on stdout.
  static void expectRefusal(const CliResult& r, const std::string& mention, int code = 2) {
    EXPECT_EQ(r.code, code) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.out, "");
  }
  // Files the command left besides the test's own (scenes, out.txt, err.txt, `keep`).
  int stray(const std::string& keep = "") const {
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir_)) {
      const std::string f = e.path().filename().string();
      n += !(f == "out.txt" || f == "err.txt" || f.ends_with(".toml") || f == keep);
    }
    return n;
  }
  std::filesystem::path dir_;
};

}  // namespace granwave::testing
