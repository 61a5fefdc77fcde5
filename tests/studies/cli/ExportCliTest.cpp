// `granwave export` end to end: a run file in, extended XYZ out (every K-th frame, the cell,
// the time, velocities and spins); a file that is not a run, or an output that would replace
// the run file, gives a one-line error, a non-zero exit and no output. (The real readers, ASE
// and MDAnalysis, read the export in export_in_readers.py.)
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "h5/File.hpp"

namespace fs = std::filesystem;

namespace {

struct Result {
  int code;
  std::string out, err;
};

class ExportCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One short dry run (0.3 s, a frame at each of 100 phases per cycle: 301 frames) shared by
    // the tests.
    dir_ = fs::temp_directory_path() / ("granwave_export_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "dry.toml") << "[contact]\nrestitution = \"dry\"\n[run]\nduration = 0.3\n";
    ASSERT_EQ(std::system(("cd '" + dir_.string() +
                           "' && '" GRANWAVE_BINARY "' simulate -q dry.toml -o run.h5 > /dev/null")
                              .c_str()),
              0);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  static Result run(const std::string& args) {
    const std::string cmd =
        "cd '" + dir_.string() + "' && '" GRANWAVE_BINARY "' " + args + " > out.txt 2> err.txt";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "out.txt"),
            slurp(dir_ / "err.txt")};
  }
  static fs::path dir_;
};

fs::path ExportCli::dir_;

TEST_F(ExportCli, WritesEveryKthFrameWithCellTimeVelocitiesAndSpins) {
  const Result r = run("export run.h5 -o every3.extxyz --every 3");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("frames          101 of 301"), std::string::npos) << r.out;
  const std::string text = slurp(dir_ / "every3.extxyz");
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 101 * (300 + 2));
  const std::string header = text.substr(0, text.find('\n', text.find('\n') + 1));
  EXPECT_EQ(header.substr(0, 4), "300\n");
  for (const char* key : {"Lattice=\"0.06 0 0 0 0.002 0 0 0 0.06\"", "velocities:R:3",
                          "angular_velocity:R:3", "radius:R:1", "Time=0 ", "units=SI"})
    EXPECT_NE(header.find(key), std::string::npos) << key << " not in " << header;
  EXPECT_NE(text.find("Time=0.006 "), std::string::npos);  // the third frame written
  fs::remove(dir_ / "every3.extxyz");
}

TEST_F(ExportCli, DefaultOutputIsTheRunFilesStemWithExtxyz) {
  ASSERT_EQ(run("export run.h5").code, 0);
  EXPECT_TRUE(fs::exists(dir_ / "run.extxyz"));
  fs::remove(dir_ / "run.extxyz");
}

TEST_F(ExportCli, FileThatIsNotARunIsRejectedWithOneLineAndNoOutput) {
  {
    auto f = granwave::h5::File::create((dir_ / "foreign.h5").string());
    f.writeDataset<double>("/data", {1.0, 2.0}, {2});
  }
  const Result r = run("export foreign.h5 -o x.extxyz");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("foreign.h5"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.extxyz"));
}

TEST_F(ExportCli, OutputThatWouldReplaceTheRunFileIsRefused) {
  const auto before = fs::file_size(dir_ / "run.h5");
  const Result r = run("export run.h5 -o ./run.h5");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("would overwrite the run file"), std::string::npos) << r.err;
  EXPECT_EQ(fs::file_size(dir_ / "run.h5"), before);
}

TEST_F(ExportCli, UnknownFormatExits2WithTheValidOne) {
  const Result r = run("export run.h5 --format pdb");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("extxyz"), std::string::npos) << r.err;
}

}  // namespace
