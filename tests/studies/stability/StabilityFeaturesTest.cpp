// The stability study's check of the paper's features (studies/stability/StabilityFeatures.hpp) on
// synthetic grids: a grid drawn as the paper describes its Fig. 3 (Huang, Sec. III) passes
// every check; the pattern this model measures (waves in the wet layer, fluid at Gamma >= 6)
// fails the ones it contradicts; a grid without the points a check needs says "not tested".
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "studies/stability/StabilityFeatures.hpp"

namespace granwave {
namespace {

LayerVerdict verdict(const std::string& state, bool wave = false, int period = 1) {
  LayerPatterns p;
  p.available = true;
  p.state = state;
  p.within_cycle_state = state;
  p.period = period;
  p.surface_wave = wave;
  return voteOverSeeds({p}, {true}, {""});
}

// Rows of states per law and frequency; `waves[law]` the Gamma values with surface waves at
// the lowest frequency.
StabilityGrid grid(const std::vector<double>& f, const std::vector<double>& gammas,
                   const std::vector<std::string> states[2][2], const std::vector<double> waves[2],
                   int wet_period = 1) {
  StabilityGrid g;
  g.frequencies = f;
  g.gammas = gammas;
  for (int law = 0; law < 2; ++law)
    for (std::size_t i = 0; i < f.size(); ++i)
      for (std::size_t j = 0; j < gammas.size(); ++j) {
        const bool wave = i == 0 && std::find(waves[law].begin(), waves[law].end(), gammas[j]) !=
                                        waves[law].end();
        g.verdicts[law].push_back(verdict(states[law][i][j], wave, law == 1 ? wet_period : 1));
      }
  return g;
}

std::map<std::string, std::string> verdicts(const StabilityGrid& g) {
  std::map<std::string, std::string> m;
  for (const FeatureCheck& c : checkPaperFeatures(g)) m[c.key] = c.verdict;
  return m;
}

const std::vector<double> kF{10, 30}, kGamma{2, 3, 4, 5, 6};
const std::string C = "crystal", L = "liquid-like";

TEST(StabilityFeatures, TheDiagramThePaperDescribesPassesEveryCheck) {
  const std::vector<std::string> states[2][2] = {{{C, L, L, L, C}, {C, C, C, C, C}},
                                                 {{C, L, L, L, C}, {C, C, C, C, C}}};
  const std::vector<double> waves[2] = {{3, 4, 5}, {}};
  // The wet layer's period differs everywhere: not a symbol of the paper's diagram.
  const auto v = verdicts(grid(kF, kGamma, states, waves, 2));
  EXPECT_EQ(v.at("dry_fluidized"), "yes");
  EXPECT_EQ(v.at("wet_fluidized"), "yes");
  EXPECT_EQ(v.at("dry_solid_again"), "yes");
  EXPECT_EQ(v.at("wet_solid_again"), "yes");
  EXPECT_EQ(v.at("surface_waves_dry_not_wet"), "yes");
  EXPECT_EQ(v.at("crystal_again_at_gamma_5"), "yes (at the highest f)");
  EXPECT_EQ(v.at("differences_shrink_with_f"), "yes");
}

TEST(StabilityFeatures, WavesInTheWetLayerAndAFluidLayerAtHighGammaFailTheirChecks) {
  const std::vector<std::string> states[2][2] = {{{C, L, L, L, L}, {C, C, C, L, C}},
                                                 {{C, L, L, L, L}, {C, C, L, L, C}}};
  const std::vector<double> waves[2] = {{}, {3, 4}};
  const auto v = verdicts(grid(kF, kGamma, states, waves));
  EXPECT_EQ(v.at("dry_fluidized"), "yes");
  EXPECT_EQ(v.at("dry_solid_again"), "no");
  EXPECT_EQ(v.at("wet_solid_again"), "no");
  EXPECT_EQ(v.at("surface_waves_dry_not_wet"), "no");
  EXPECT_EQ(v.at("crystal_again_at_gamma_5"), "no");
  // 2 differing points at 10 Hz (the waves), 1 at 30 Hz (Gamma = 4): fewer, so shrinking.
  EXPECT_EQ(v.at("differences_shrink_with_f"), "yes");
}

TEST(StabilityFeatures, FluidLayerAtGamma2FailsTheFluidizationCheck) {
  const std::vector<std::string> states[2][2] = {{{L, L, L, L, C}, {C, C, C, C, C}},
                                                 {{C, L, L, L, C}, {C, C, C, C, C}}};
  const std::vector<double> waves[2] = {{3, 4, 5}, {}};
  const auto v = verdicts(grid(kF, kGamma, states, waves));
  EXPECT_EQ(v.at("dry_fluidized"), "no");
  EXPECT_EQ(v.at("wet_fluidized"), "yes");
}

TEST(StabilityFeatures, PointsTheChecksNeedMissingFromTheGridAreNotTested) {
  const std::vector<double> f{20}, gammas{2, 4};
  const std::vector<std::string> states[2][2] = {{{C, L}, {}}, {{C, L}, {}}};
  const std::vector<double> waves[2] = {{}, {}};
  const auto v = verdicts(grid(f, gammas, states, waves));
  EXPECT_EQ(v.at("dry_solid_again").rfind("not tested", 0), 0u) << v.at("dry_solid_again");
  EXPECT_EQ(v.at("crystal_again_at_gamma_5").rfind("not tested", 0), 0u);
  EXPECT_EQ(v.at("differences_shrink_with_f").rfind("not tested", 0), 0u);
  EXPECT_EQ(v.at("dry_fluidized"), "yes");
}

TEST(StabilityFeatures, UnclassifiedPointsAreLeftOutAndNamedNotReadAsAnAnswer) {
  const std::vector<std::string> states[2][2] = {{{C, L, L, L, C}, {C, C, C, C, C}},
                                                 {{C, L, L, L, C}, {C, C, C, C, C}}};
  const std::vector<double> waves[2] = {{3, 4, 5}, {}};
  StabilityGrid g = grid(kF, kGamma, states, waves);
  // Every wet seed failed at 10 Hz, Gamma = 4 and at 30 Hz, Gamma = 5.
  g.verdicts[1][2] = voteOverSeeds({LayerPatterns{}}, {false}, {"collapse"});
  g.verdicts[1][5 + 3] = voteOverSeeds({LayerPatterns{}}, {false}, {"collapse"});
  const auto v = verdicts(g);
  EXPECT_EQ(v.at("surface_waves_dry_not_wet"), "yes (not classified at Gamma = 4)");
  EXPECT_EQ(v.at("wet_fluidized"), "yes (not classified at Gamma = 4)");
  EXPECT_EQ(v.at("crystal_again_at_gamma_5").rfind("not tested", 0), 0u)
      << v.at("crystal_again_at_gamma_5");
  // 30 Hz now has 4 comparable points, none differing: 0 of 4 < 2 of 4 at 10 Hz.
  EXPECT_EQ(v.at("differences_shrink_with_f"), "yes");
  // A frequency with nothing to compare cannot say whether differences shrank.
  for (std::size_t j = 0; j < kGamma.size(); ++j)
    g.verdicts[1][5 + j] = voteOverSeeds({LayerPatterns{}}, {false}, {"collapse"});
  EXPECT_EQ(verdicts(g).at("differences_shrink_with_f").rfind("not tested", 0), 0u);
}

TEST(StabilityFeatures, DifferencesCountThePaperSymbolsNotThePeriod) {
  const std::vector<std::string> states[2][2] = {{{C, L, L, L, C}, {C, C, C, C, C}},
                                                 {{C, L, L, L, C}, {C, C, C, C, C}}};
  const std::vector<double> waves[2] = {{}, {}};
  const StabilityGrid g = grid(kF, kGamma, states, waves, 2);
  EXPECT_EQ(g.symbolDifferencesPerFrequency(), (std::vector<double>{0, 0}));
  EXPECT_EQ(g.periodDifferencesPerFrequency(), (std::vector<double>{5, 5}));
  // No difference at the lowest f: nothing to shrink.
  EXPECT_EQ(verdicts(g).at("differences_shrink_with_f"), "no");
}

// The layer measured at 10 Hz, Gamma = 6-7 (docs/classification.md): liquid-like by the bonds
// over 15 cycles, ordered and compact in every cycle. Each criterion answers its own checks.
TEST(StabilityFeatures, EachSolidCriterionAnswersTheStateChecksOnItsOwn) {
  const std::vector<std::string> states[2][2] = {{{C, L, L, L, L}, {C, C, C, C, C}},
                                                 {{C, L, L, L, L}, {C, C, C, C, C}}};
  const std::vector<double> waves[2] = {{}, {}};
  StabilityGrid g = grid(kF, kGamma, states, waves);
  for (int law = 0; law < 2; ++law) {
    LayerPatterns p;
    p.available = true;
    p.state = L;
    p.within_cycle_state = C;
    p.period = 1;
    g.verdicts[law][4] = voteOverSeeds({p}, {true}, {""});  // 10 Hz, Gamma = 6
  }
  const auto v = verdicts(g);
  EXPECT_EQ(v.at("dry_solid_again"), "no");
  EXPECT_EQ(v.at("wet_solid_again"), "no");
  EXPECT_EQ(v.at("dry_solid_again_within_cycle"), "yes");
  EXPECT_EQ(v.at("wet_solid_again_within_cycle"), "yes");
  EXPECT_EQ(g.at(0, 0, 4).stateBy(SolidCriterion::within_cycle).value, C);
}

}  // namespace
}  // namespace granwave
