// The stability study's particle grid (studies/stability.toml: f = 10, 15, 20, 30 Hz, Gamma =
// 2-7, 150 cycles), wet with three seeds and dry with two, on the scenes' defaults (TC model
// on, contact.sleep = "auto"): every run reaches its end without a contact the engine does not
// resolve. Before the sleep rule's alarm (docs/physics.md, "Resting contacts", item 7) nine of
// 240 such runs (five seeds), all wet, stopped with exit 3 (docs/performance.md, "The
// event-driven engine"). Why these seeds: a wet failure that stops 9 of 120 wet runs is missed
// by the 72 wet runs here with probability (1 - 9/120)^72 = 0.4 %, one that stops 1 in 100
// with 49 %; a dry failure of 1 in 100 is missed by the 48 dry runs with 62 % (no dry run has
// stopped in any seed). Five seeds of both would take 1.9 times the cost: CI's 30 minutes.
// About 350 CPU-s in a Release build, so the label `grid`: the sanitizer pass of
// scripts/test.sh leaves it out (its runs take the code paths of the shorter tests).
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "particles/EdSimulation.hpp"
#include "particles/InitialState.hpp"
#include "scene/SceneParser.hpp"

using namespace granwave;

namespace {

using GridPoint = std::tuple<std::string, int, int>;  // law, f (Hz), Gamma

class StabilityGrid : public ::testing::TestWithParam<GridPoint> {};

// The paper's scene of `law` at this drive and seed runs its 150 cycles to the end.
void expectFinishes(const std::string& law, int f, int gamma, int seed) {
  const std::vector<std::string> set = {
      "drive.frequency=" + std::to_string(f), "drive.gamma=" + std::to_string(gamma),
      "run.seed=" + std::to_string(seed), "run.duration=" + std::to_string(150.0 / f)};
  const Scene s =
      parseSceneFile(std::string(GRANWAVE_SOURCE_DIR) + "/scenes/paper-" + law + ".toml", set);
  const EngineConfig c = engineConfig(s);
  EdSimulation sim(c, initialCondition(s, c));
  const std::string where = law + ", f = " + std::to_string(f) +
                            " Hz, Gamma = " + std::to_string(gamma) + ", seed " +
                            std::to_string(seed);
  bool completed = false;
  EXPECT_NO_THROW(completed = sim.run().completed) << where;
  EXPECT_TRUE(completed) << where;
  EXPECT_DOUBLE_EQ(sim.now(), s.run.duration) << where;
}

TEST_P(StabilityGrid, SeedsRunTheirHundredFiftyCyclesWithoutCollapse) {
  const auto& [law, f, gamma] = GetParam();
  const int seeds = law == "wet" ? 3 : 2;
  for (int seed = 1; seed <= seeds; ++seed) expectFinishes(law, f, gamma, seed);
}

INSTANTIATE_TEST_SUITE_P(PaperGrid, StabilityGrid,
                         ::testing::Combine(::testing::Values("dry", "wet"),
                                            ::testing::Values(10, 15, 20, 30),
                                            ::testing::Values(2, 3, 4, 5, 6, 7)),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_f" +
                                  std::to_string(std::get<1>(info.param)) + "_Gamma" +
                                  std::to_string(std::get<2>(info.param));
                         });

}  // namespace
