// `granwave fields` end to end: a run file in, a fields file and its XDMF sidecar out; every
// kind of bad input file gives a one-line error naming the file, a non-zero exit and no output.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "h5/File.hpp"

namespace fs = std::filesystem;

namespace {

struct Result {
  int code;
  std::string out, err;
};

class FieldsCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One short wet run (4 s = 40 cycles) shared by the tests: a copy of the one ctest's
    // fixture made (GRANWAVE_FIELDS_CLI_RUN, cli/fields_cli_run.sh), or made here.
    dir_ = fs::temp_directory_path() / ("granwave_fields_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    if (const char* made = std::getenv("GRANWAVE_FIELDS_CLI_RUN")) {
      for (const char* name : {"wet.toml", "wet.h5", "simulate.txt"})
        fs::copy_file(fs::path(made) / name, dir_ / name);
      return;
    }
    std::ofstream(dir_ / "wet.toml") << "[contact]\nrestitution = \"wet\"\n[run]\nduration = 4\n";
    ASSERT_EQ(
        std::system(("cd '" + dir_.string() +
                     "' && '" GRANWAVE_BINARY "' simulate -q wet.toml -o wet.h5 > simulate.txt")
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
  Result run(const std::string& args) {
    const std::string cmd =
        "cd '" + dir_.string() + "' && '" GRANWAVE_BINARY "' " + args + " > out.txt 2> err.txt";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "out.txt"),
            slurp(dir_ / "err.txt")};
  }
  void expectCleanFailure(const Result& r, const std::string& mention) {
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "f.h5"));
    EXPECT_FALSE(fs::exists(dir_ / "f.xdmf"));
  }
  static fs::path dir_;
};
fs::path FieldsCli::dir_;

}  // namespace

// One period detector for every command (coarse_grain/PeriodDetector.hpp, runPeriod): `fields`
// reports the period `simulate` reported for the same run, whatever window it averages over;
// two rules could give a bistable layer two periods.
TEST_F(FieldsCli, GivesTheRunThePeriodSimulateGaveIt) {
  const std::string sim = slurp(dir_ / "simulate.txt");
  const auto at = sim.find("centre of mass  period ");
  ASSERT_NE(at, std::string::npos) << sim;
  const std::string period = sim.substr(at + 23, sim.find('T', at + 23) - (at + 23));
  for (const std::string discard : {"", " --discard 20"}) {  // auto, and a late start
    const Result r = run("fields wet.h5 -o f.h5" + discard);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("layer period    " + period + "T"), std::string::npos)
        << "simulate: " << period << "T; fields" << discard << ":\n"
        << r.out;
    EXPECT_NE(r.out.find("period-2 state  "), std::string::npos) << r.out;
    fs::remove(dir_ / "f.h5");
    fs::remove(dir_ / "f.xdmf");
  }
}

TEST_F(FieldsCli, WritesFieldsFileWithGridProfilesFrontsAndSidecar) {
  const Result r = run("fields wet.h5 -o f.h5 --period 2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("pooled"), std::string::npos) << r.out;
  // The velocity-jump fronts with their transits through the layer's mass (FrontTransit.hpp).
  EXPECT_NE(r.out.find("velocity front  t/T "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" (mass 0.1-0.5), "), std::string::npos) << r.out;
  auto f = granwave::h5::File::openReadOnly((dir_ / "f.h5").string());
  EXPECT_EQ(f.shape("/fields/temperature"), (granwave::h5::Shape{200, 40, 30}));
  EXPECT_EQ(f.shape("/profiles/rms_velocity_x"), (granwave::h5::Shape{200, 40}));
  EXPECT_EQ(f.readStringAttribute("/fields/temperature", "unit"), "J");
  EXPECT_EQ(f.readAttribute<std::int64_t>("/parameters", "cycles_per_window"), 2);
  EXPECT_TRUE(f.isDataset("/fronts/speed"));
  EXPECT_TRUE(f.isDataset("/xdmf/p0199/velocity"));
  const std::string xdmf = slurp(dir_ / "f.xdmf");
  EXPECT_NE(xdmf.find("f.h5:/xdmf/p0000/temperature"), std::string::npos);
  EXPECT_NE(xdmf.find("CollectionType=\"Temporal\""), std::string::npos);
  fs::remove(dir_ / "f.h5");
  fs::remove(dir_ / "f.xdmf");
}

// The state-conditioned averages double the fields' memory, so they are made only on request
// (--state-fields); then /states counts the windows pooled as period 1 or as period 2.
TEST_F(FieldsCli, StateFieldsAreWrittenOnlyWhenAsked) {
  for (const bool asked : {false, true}) {
    const Result r = run(std::string("fields wet.h5 -o f.h5") + (asked ? " --state-fields" : ""));
    ASSERT_EQ(r.code, 0) << r.err;
    {
      auto f = granwave::h5::File::openReadOnly((dir_ / "f.h5").string());
      ASSERT_EQ(f.isGroup("/states"), asked);
      if (asked) {
        const auto w1 = f.readAttribute<std::int64_t>("/states", "windows_period1");
        const auto w2 = f.readAttribute<std::int64_t>("/states", "windows_period2");
        EXPECT_GE(w1, 0);
        EXPECT_GE(w2, 0);
        // The state averages start with the series' first window after the steady-state
        // detector fired (docs/classification.md), so they hold at most the series' windows.
        EXPECT_GE(w1 + w2, 1);
        EXPECT_LE(w1 + w2,
                  static_cast<std::int64_t>(f.shape("/period_doubling/f2_strength").at(0)));
      }
    }
    fs::remove(dir_ / "f.h5");
    fs::remove(dir_ / "f.xdmf");
  }
}

TEST_F(FieldsCli, TextFileIsRejected) {
  std::ofstream(dir_ / "text.h5") << "not hdf5\n";
  expectCleanFailure(run("fields text.h5 -o f.h5"), "text.h5");
}

TEST_F(FieldsCli, ForeignHdf5FileIsRejected) {
  {
    auto f = granwave::h5::File::create((dir_ / "foreign.h5").string());
    f.writeDataset<double>("/data", {1.0, 2.0}, {2});
  }
  expectCleanFailure(run("fields foreign.h5 -o f.h5"), "not an H5MD file");
}

TEST_F(FieldsCli, TruncatedRunIsRejected) {
  const std::string bytes = slurp(dir_ / "wet.h5");
  std::ofstream(dir_ / "cut.h5", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  expectCleanFailure(run("fields cut.h5 -o f.h5"), "cut.h5");
}

TEST_F(FieldsCli, StridedRunIsRejectedWithTheRemedy) {
  std::ofstream(dir_ / "strided.toml")
      << "[contact]\nrestitution = \"dry\"\n[run]\nduration = 0.5\ntrajectory_stride = 2\n";
  ASSERT_EQ(run("simulate -q strided.toml -o strided.h5").code, 0);
  expectCleanFailure(run("fields strided.h5 -o f.h5"), "trajectory_stride");
}

TEST_F(FieldsCli, UndrivenRunIsRejected) {
  std::ofstream(dir_ / "gas.toml")
      << "[container]\nperiodic_x = true\nperiodic_z = true\n[drive]\nfrequency = 0\n"
         "[contact]\ntc = \"off\"\nrestitution = \"constant\"\ne = 1\n[initial]\n"
         "temperature = 1e-6\n[run]\ngravity = 0\nduration = 0.05\n";
  ASSERT_EQ(run("simulate -q gas.toml -o gas.h5").code, 0);
  expectCleanFailure(run("fields gas.h5 -o f.h5"), "driven");
}

// A NaN would spread through every average it enters and the file would look fine.
TEST_F(FieldsCli, RunWithANonFiniteFrameIsRefusedNamingTheFrame) {
  fs::copy_file(dir_ / "wet.h5", dir_ / "nan.h5", fs::copy_options::overwrite_existing);
  {
    const hid_t file = H5Fopen((dir_ / "nan.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    const hid_t data = H5Dopen2(file, "/particles/all/position/value", H5P_DEFAULT);
    const hid_t space = H5Dget_space(data);
    const hsize_t start[3] = {123, 7, 0}, count[3] = {1, 1, 1};
    H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr);
    const hid_t one = H5Screate_simple(3, count, nullptr);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_GE(H5Dwrite(data, H5T_NATIVE_DOUBLE, one, space, H5P_DEFAULT, &nan), 0);
    H5Sclose(one);
    H5Sclose(space);
    H5Dclose(data);
    H5Fclose(file);
  }
  const Result r = run("fields nan.h5 -o f.h5");
  EXPECT_EQ(r.code, 2) << r.err;
  expectCleanFailure(r, "nan.h5: frame 123 (t = ");
}

TEST_F(FieldsCli, BadPeriodOptionIsRejected) {
  const Result r = run("fields wet.h5 -o f.h5 --period 7");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--period"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "f.h5"));
}
