// The tiny wave-fronts study (tests/studies/data/tiny-wave-fronts.toml).
//
// Without the TC model the wet law is completely inelastic below its onset velocity
// (e = 0), and an event-driven engine then meets inelastic collapse, infinitely many
// collisions in finite time, as soon as particles rest on each other (McNamara & Young,
// Phys. Fluids A 4, 496 (1992)): every wet failure-map run without TC stops at a finite time
// within its duration. The continuum's impact front in the dry layer travels up from the plate:
// its lab-frame speed is positive beyond 3 of its stated sigma. (The wet continuum doubles its
// period and its impacts heat the layer to only 0.2-0.6 T0, below the front threshold of
// 0.5 T0 for more than a phase or two, so it has no front to test; docs/hydro.md.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tests/studies/contract/TinyStudy.hpp"

namespace {

constexpr char kKind[] = "wave-fronts";
using WaveFrontsResults = granwave::testing::TinyStudyTest<kKind>;
const std::string kRoot = "/results/wave_fronts";
constexpr double kFailureDuration = 0.5;  // s, the tiny study file's [failure] duration

TEST_F(WaveFrontsResults, WetLayerWithoutTheTcModelCollapsesInelastically) {
  const auto times = study().series(kRoot + "/failure/ed_no_tc_collapse_time_wet");
  ASSERT_FALSE(times.empty());
  for (double t : times) {
    EXPECT_TRUE(std::isfinite(t)) << "the wet run without TC did not collapse";
    EXPECT_GT(t, 0);
    EXPECT_LE(t, kFailureDuration);
  }
}

TEST_F(WaveFrontsResults, DryContinuumImpactFrontTravelsUpFromThePlate) {
  const std::string g = kRoot + "/hydro_dry_velocity";
  const double v = study().value(g, "all"), e = study().value(g, "all_error");
  EXPECT_GT(v, 3 * e) << v << " +- " << e << " m/s";
}

TEST_F(WaveFrontsResults, DryContinuumFrontByTheVelocityJumpTravelsUpAtN150) {
  // The velocity-jump tracker (coarse_grain/ImpactFrontTracker.hpp) on the hydro run of the
  // N sweep's first count: a front rising from the plate, beyond 3 of its stated sigma.
  const auto v = study().series(kRoot + "/n_sweep/dry/hydro_tracked_speed");
  const auto e = study().series(kRoot + "/n_sweep/dry/hydro_tracked_speed_error");
  ASSERT_FALSE(v.empty());
  EXPECT_GT(v[0], 3 * e[0]) << v[0] << " +- " << e[0] << " m/s";
}

TEST_F(WaveFrontsResults, DryContinuumFrontPassesTheLowerHalfOfTheMassUpwardAtN150) {
  // Its transit from 10 % to 50 % of the layer's mass below it (coarse_grain/FrontTransit.hpp):
  // a speed, upward; the particles' transits (whole run and period-2 windows) are written
  // beside it, one per count.
  const auto dense = study().series(kRoot + "/n_sweep/dry/hydro_tracked_transit_dense");
  ASSERT_EQ(dense.size(), 1u);
  EXPECT_GT(dense[0], 0.0) << dense[0] << " m/s";
  // A speed comes from a front that passed both fractions, counted as such.
  const std::string counts = kRoot + "/n_sweep/dry/hydro_tracked_transit_dense_";
  const double fronts = study().series(counts + "fronts").at(0);
  const double reached = study().series(counts + "reached").at(0);
  const double resolved = study().series(counts + "resolved").at(0);
  EXPECT_GE(resolved, 1.0);
  EXPECT_LE(resolved, reached);
  EXPECT_LE(reached, fronts);
  EXPECT_EQ(study().series(kRoot + "/n_sweep/dry/tracked_transit_upper_lower_bound").size(), 1u);
  EXPECT_EQ(study().series(kRoot + "/n_sweep/dry/tracked_period2_transit_dense").size(), 1u);
}

}  // namespace

namespace {

// One seed and max_seeds = 1: every bootstrap resample is the one seed, so the verdict recurs
// in all of them, and no seed is added (docs/studies.md, "Verdict stability").
TEST_F(WaveFrontsResults, WithOneSeedAndNoRoomForMoreTheVerdictRestsOnThatSeedAlone) {
  for (const char* law : {"dry", "wet"}) {
    const std::string g = kRoot + "/models/" + law;
    EXPECT_DOUBLE_EQ(study().value(g, "verdict_agreement"), 1.0) << law;
    EXPECT_DOUBLE_EQ(study().value(g, "verdict_seeds"), 1.0) << law;
    EXPECT_DOUBLE_EQ(study().value(g, "front_tolerance"), 0.15) << law;
  }
}

}  // namespace

namespace {

std::vector<std::string> splitList(const std::string& text) {  // "a; b; c" -> {a, b, c}
  std::vector<std::string> out;
  for (std::size_t from = 0;;) {
    const std::size_t to = text.find("; ", from);
    out.push_back(text.substr(from, to - from));
    if (to == std::string::npos) return out;
    from = to + 2;
  }
}

// Cost per answer at equal accuracy (docs/studies.md): one scene per law on the paper's scene
// and per law and count of the N sweep (one count in the tiny study), each naming as its
// cheapest model one that its own verdicts say reproduces the particles, with a CPU time.
TEST_F(WaveFrontsResults, EveryScenesCheapestModelIsOneThatReproducesTheParticles) {
  const std::string root = kRoot + "/cost/cheapest/scene_";
  const granwave::h5::File& f = study().file();
  for (int k = 0; k < 4; ++k) {
    const std::string g = root + std::to_string(k);
    const auto models = splitList(f.readStringAttribute(g, "models"));
    const auto reproduces = splitList(f.readStringAttribute(g, "reproduces"));
    const auto cpu = study().series(g + "/cpu_seconds_per_answer");
    ASSERT_EQ(models.size(), reproduces.size()) << g;
    ASSERT_EQ(models.size(), cpu.size()) << g;
    const auto at = std::find(models.begin(), models.end(), f.readStringAttribute(g, "cheapest"));
    ASSERT_NE(at, models.end()) << g;
    const auto i = static_cast<std::size_t>(at - models.begin());
    EXPECT_EQ(reproduces[i], "yes") << g << ": " << *at;
    EXPECT_GT(cpu[i], 0) << g << ": " << *at;
  }
  EXPECT_FALSE(f.exists(root + "4")) << "the tiny study has 4 scenes";
}

}  // namespace

namespace {

// The energy budget phase by phase (docs/studies.md): over its periodic window the smooth
// continuum stores nothing, so the plate's work equals the losses to the budget's closure
// (2e-3 mJ per cycle or better, docs/hydro.md; 1 % of about 3 mJ here); the particles' budget
// is recorded, with a positive work and both losses.
TEST_F(WaveFrontsResults, EnergyBudgetOfTheContinuumBalancesOverItsWindowAndTheParticlesHaveOne) {
  for (const char* law : {"dry", "wet"}) {
    const std::string g = kRoot + "/energy_budget/" + law;
    const double work = study().value(g + "/continuum_smooth", "plate_work_per_cycle");
    const double loss = study().value(g + "/continuum_smooth", "pair_loss_per_cycle") +
                        study().value(g + "/continuum_smooth", "wall_loss_per_cycle");
    EXPECT_NEAR(loss, work, 0.01 * work) << law;
    for (const char* term : {"plate_work_per_cycle", "pair_loss_per_cycle", "wall_loss_per_cycle"})
      EXPECT_GT(study().value(g + "/particles", term), 0) << law << " " << term;
  }
}

}  // namespace
