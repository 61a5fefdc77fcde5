// `granwave hydro` end to end: a short periodic run writes plate- and lab-frame fields,
// fronts and solver statistics; bad scenes fail in one line with nothing written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "h5/File.hpp"

namespace fs = std::filesystem;

namespace {
struct Result {
  int code;
  std::string out, err;
};
class HydroCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("granwave_hydro_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  Result run(const std::string& scene_text, const std::string& args) {
    std::ofstream(dir_ / "s.toml") << "[contact]\nrestitution = \"dry\"\n" << scene_text;
    const std::string cmd = "cd '" + dir_.string() + "' && '" GRANWAVE_BINARY "' hydro -q s.toml " +
                            args + " > out.txt 2> err.txt";
    const int st = std::system(cmd.c_str());
    return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, slurp(dir_ / "out.txt"), slurp(dir_ / "err.txt")};
  }
  fs::path dir_;
};
}  // namespace

TEST_F(HydroCli, CoarseRunReachesPeriodicStateAndWritesFields) {
  const Result r =
      run("[hydro]\ncells = 100\n[run]\nphases_per_cycle = 50\nduration = 1.2\n", "-o h.h5");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("periodic state  reached"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("layer           fluidised"), std::string::npos) << r.out;
  auto f = granwave::h5::File::openReadOnly((dir_ / "h.h5").string());
  const auto shape = f.shape("/plate_frame/temperature");
  ASSERT_EQ(shape.size(), 2u);
  EXPECT_EQ(shape[1], 100u);
  EXPECT_EQ(shape[0] % 50, 0u);                         // whole cycles of 50 phases
  EXPECT_EQ(f.shape("/profiles/temperature")[1], 40u);  // the coarse-graining grid, named as
  EXPECT_EQ(f.shape("/grid/z")[0], 40u);                // in a fields file
  EXPECT_GT(f.readAttribute<std::int64_t>("/solver", "steps"), 0);
  EXPECT_EQ(f.readStringAttribute("/plate_frame/temperature", "unit"), "J");
}

// The summary gives the velocity-jump front with its transit speeds through the layer's mass
// (coarse_grain/FrontTransit.hpp): on the paper's layer at 400 phases per cycle the impact front
// climbs through several phases, so its fit and both transits are measured speeds, not bounds.
TEST_F(HydroCli, SummaryGivesTheVelocityFrontWithItsTransitsThroughTheLayer) {
  const Result r = run("[run]\nphases_per_cycle = 400\nduration = 1.2\n", "-o h.h5");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto at = r.out.find("velocity front  t/T ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
  EXPECT_NE(line.find(" m/s (fit, lab); transits "), std::string::npos) << line;
  EXPECT_NE(line.find(" m/s (mass 0.1-0.5), "), std::string::npos) << line;
  EXPECT_NE(line.find(" m/s (0.5-0.9)"), std::string::npos) << line;
  EXPECT_EQ(line.find("not reached"), std::string::npos) << line;
  EXPECT_EQ(line.find("> "), std::string::npos) << line;
}

TEST_F(HydroCli, HardWallsRunToThePeriodicStateAndTheSummaryNamesThem) {
  const Result r =
      run("[hydro]\nwalls = \"hard\"\n[run]\nphases_per_cycle = 50\nduration = 1.2\n", "-o h.h5");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("hard walls"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("periodic state  reached"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(dir_ / "h.h5"));
}

TEST_F(HydroCli, UndrivenSceneIsRejectedAndNothingWritten) {
  const Result r = run("[drive]\nfrequency = 0\n", "-o h.h5");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("driven"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "h.h5"));
  // A plate at rest (Gamma = 0) has no front to find: no "front" of 1e-31 m/s at T = inf.
  const Result still = run("", "-o h.h5 --set drive.gamma=0");
  EXPECT_EQ(still.code, 2) << still.err;
  EXPECT_NE(still.err.find("drive.gamma or drive.amplitude > 0"), std::string::npos) << still.err;
  EXPECT_EQ(still.out, "");
  EXPECT_FALSE(fs::exists(dir_ / "h.h5"));
}

// Walton's law with e_t0 = -1 makes every contact smooth: the rough continuum's rotational
// temperature has no source. The scene is refused naming both keys and the equivalent choice.
TEST_F(HydroCli, RoughParticlesWithSmoothContactsAreRefusedNamingTheKeys) {
  const Result r =
      run("", "-o h.h5 --set contact.tangential_limit=-1 --set hydro.particles=\"rough\"");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("contact.tangential_limit > -1 for hydro.particles = \"rough\""),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("use hydro.particles = \"smooth\""), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "h.h5"));
}

TEST_F(HydroCli, BadHydroKeyIsRejectedWithTheValidChoices) {
  const Result r = run("[hydro]\ntransport = \"navier\"\n", "-o h.h5");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("hydro.transport"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("garzo-dufty"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "h.h5"));
}

// The 2D run measures its layer's surface as the particles' runs do: the run file's /surface
// group (the fields file's layout) over the second half of the run, and the same summary line.
TEST_F(HydroCli, TwoDimensionalRunWritesTheSurfaceSpectrumOfItsSecondHalf) {
  const Result r = run("[run]\nphases_per_cycle = 20\nduration = 0.3\n",
                       "-o h.h5 --set hydro.dimensions=2 --set hydro.columns=2 --set "
                       "hydro.cells=10 --set container.periodic_x=true");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("surface spectrum over 1 windows of 4 cycles"), std::string::npos) << r.out;
  auto f = granwave::h5::File::openReadOnly((dir_ / "h.h5").string());
  EXPECT_EQ(f.readAttribute<std::int64_t>("/surface", "columns"), 30);  // one per d of 30 d
  EXPECT_EQ(f.readAttribute<std::int64_t>("/surface", "cycles"), 4);    // cycles 5-8 of 8
  EXPECT_EQ(f.readAttribute<std::int64_t>("/surface", "records_per_cycle"), 20);
  EXPECT_EQ(f.shape("/surface/recent_height"), (granwave::h5::Shape{80, 30}));
  // A layer seeded with 1 % of noise in its column masses has no wave: its f/2 amplitude is
  // far below the detector's threshold of 0.5 d.
  EXPECT_LT(f.readAttribute<double>("/surface", "amplitude_d"), 0.1);
  EXPECT_EQ(f.readAttribute<double>("/surface", "wave_fraction"), 0.0);
}

// With hydro.energy_budget the 2D run writes the 1D run's /budget group (the window's phases)
// and its summary line; the budget closes to the integration error (rtol 1e-4: asserted within
// 1 % of the plate's work over the window; measured about 1e-4 on the paper's dry scene).
TEST_F(HydroCli, TwoDimensionalRunWritesItsEnergyBudgetWhenAsked) {
  const std::string keys =
      "-o h.h5 --set hydro.dimensions=2 --set hydro.columns=2 --set hydro.cells=10 --set "
      "container.periodic_x=true";
  const std::string scene = "[run]\nphases_per_cycle = 20\nduration = 0.3\n";
  const Result r = run(scene, keys + " --set hydro.energy_budget=true");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("energy          per cycle: plate work"), std::string::npos) << r.out;
  auto f = granwave::h5::File::openReadOnly((dir_ / "h.h5").string());
  const std::vector<double> work = f.readDataset<double>("/budget/plate_work");
  ASSERT_EQ(work.size(), 40u);  // the window: the last 2 cycles of 20 phases
  double closure = 0, throughput = 0;
  for (const char* loss : {"collisional_loss", "friction_loss", "wall_loss"})
    for (double x : f.readDataset<double>(std::string("/budget/") + loss)) closure += x;
  for (double x : f.readDataset<double>("/budget/energy_change")) closure += x;
  for (double x : work) closure -= x, throughput += std::abs(x);
  EXPECT_GT(throughput, 0);
  EXPECT_LT(std::abs(closure), 1e-2 * throughput);
  fs::remove(dir_ / "h.h5");
  ASSERT_EQ(run(scene, keys).code, 0);
  EXPECT_FALSE(granwave::h5::File::openReadOnly((dir_ / "h.h5").string()).isGroup("/budget"));
}
