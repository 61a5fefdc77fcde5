#include "studies/stability/StabilityFeatures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>

#include "studies/contract/StudyScenes.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

namespace {

using GammaRange = std::function<bool(double)>;

bool mid(double gm) { return gm >= 3 && gm <= 5; }
bool low(double gm) { return gm <= 2; }
bool high(double gm) { return gm >= 6; }

std::string votes(const Vote<std::string>& v) {
  return fmt::format("{} ({}/{})", v.value, v.count, v.of);
}

std::string qualified(std::string verdict, const std::string& missing) {
  if (missing.empty() || verdict.starts_with("not tested")) return verdict;
  return verdict + " (not classified at Gamma = " + missing + ")";
}

// The grid's lowest frequency, where the paper's first three features are stated.
struct LowestFrequency {
  const StabilityGrid& grid;
  std::size_t i0;
  double f0;

  explicit LowestFrequency(const StabilityGrid& g)
      : grid(g),
        i0(static_cast<std::size_t>(std::min_element(g.frequencies.begin(), g.frequencies.end()) -
                                    g.frequencies.begin())),
        f0(g.frequencies[i0]) {}

  const LayerVerdict& at(int law, std::size_t j) const { return grid.at(law, i0, j); }

  // The states by `c` for the Gamma values in `in`, e.g. "Gamma = 6: liquid-like (3/3), 7:
  // ..."; with `numbers` the measurements the state comes from.
  std::string states(int law, const GammaRange& in, SolidCriterion c, bool numbers = false) const {
    std::string s;
    for (std::size_t j = 0; j < grid.gammas.size(); ++j) {
      const LayerVerdict& v = at(law, j);
      if (!in(grid.gammas[j]) || !v.classified()) continue;
      s += (s.empty() ? "Gamma = " : ", ") + formatCompact(grid.gammas[j]) + ": " +
           votes(v.stateBy(c));
      if (numbers && c == SolidCriterion::bonds)
        s += fmt::format(", bonds kept {:.2f} over 15 cycles, {:.2f} over one", v.bonds_kept,
                         v.bonds_kept_per_cycle);
      if (numbers && c == SolidCriterion::within_cycle)
        s += fmt::format(", {:.1f} neighbours and psi6 {:.2f} when most compact, {:.1f} on the lid",
                         v.within_cycle_coordination, v.within_cycle_psi6, v.lid_row);
    }
    return s.empty() ? std::string("no classified point") : s;
  }

  // Gamma values in `in` where `law` (or, with law = -1, either law) has no classified run: a
  // check that needs them says so instead of reading them as an answer.
  std::string unclassified(int law, const GammaRange& in) const {
    std::string s;
    for (std::size_t j = 0; j < grid.gammas.size(); ++j) {
      if (!in(grid.gammas[j])) continue;
      const bool missing =
          law < 0 ? !at(0, j).classified() || !at(1, j).classified() : !at(law, j).classified();
      if (missing) s += (s.empty() ? "" : ", ") + formatCompact(grid.gammas[j]);
    }
    return s;
  }
};

// Fluid for Gamma in [3, 5] and not at Gamma = 2; solid again at Gamma >= 6; by criterion `c`.
void fluidizationChecks(const LowestFrequency& lf, int law, SolidCriterion c,
                        std::vector<FeatureCheck>& out) {
  const std::vector<double>& gammas = lf.grid.gammas;
  bool fluid_mid = true, solid_low = true, solid_high = true;
  bool any_low = false, any_high = false, any_mid = false;
  for (std::size_t j = 0; j < gammas.size(); ++j) {
    const LayerVerdict& v = lf.at(law, j);
    const double gm = gammas[j];
    if (!v.classified()) continue;
    const bool liquid = v.stateBy(c).value == "liquid-like";
    if (mid(gm)) any_mid = true, fluid_mid &= liquid;
    if (low(gm)) any_low = true, solid_low &= !liquid;
    if (high(gm)) any_high = true, solid_high &= !liquid;
  }
  const std::string fluidized = !any_mid ? "not tested (no classified Gamma in [3, 5])"
                                : !(fluid_mid && (!any_low || solid_low)) ? "no"
                                : any_low                                 ? "yes"
                                          : "yes for Gamma in [3, 5]; Gamma <= 2 not tested";
  const auto to5 = [](double gm) { return gm <= 5; };
  const std::string name = kLawNames[law];
  const std::string key = criterionKey(c), by = criterionName(c);
  out.push_back(
      {name + "_fluidized" + key,
       fmt::format("{}: fluidized for Gamma in [3, 5], not at Gamma = 2 (f = {:g} Hz; {})", name,
                   lf.f0, by),
       lf.states(law, to5, c), qualified(fluidized, lf.unclassified(law, to5))});
  out.push_back({name + "_solid_again" + key,
                 fmt::format("{}: solid again at Gamma >= 6 (f = {:g} Hz; {})", name, lf.f0, by),
                 lf.states(law, high, c, true),
                 qualified(any_high ? (solid_high ? "yes" : "no")
                           : std::any_of(gammas.begin(), gammas.end(), high)
                               ? "not tested (no classified Gamma >= 6)"
                               : "not tested (no Gamma >= 6)",
                           lf.unclassified(law, high))});
}

// Surface waves dry and none wet for Gamma in [3, 5]. Points where either law is unclassified
// say nothing about the pattern: left out, and named.
FeatureCheck surfaceWaveCheck(const LowestFrequency& lf) {
  bool dry_waves = true, wet_none = true, any_wave_point = false;
  std::string seen[2];
  for (std::size_t j = 0; j < lf.grid.gammas.size(); ++j) {
    const double gm = lf.grid.gammas[j];
    for (int law = 0; law < kLaws; ++law)
      if (lf.at(law, j).classified() && lf.at(law, j).surface_wave.value)
        seen[law] += (seen[law].empty() ? "" : ", ") + formatCompact(gm);
    const LayerVerdict &a = lf.at(0, j), &b = lf.at(1, j);
    if (!mid(gm) || !a.classified() || !b.classified()) continue;
    any_wave_point = true;
    dry_waves &= a.surface_wave.value;
    wet_none &= !b.surface_wave.value;
  }
  return {"surface_waves_dry_not_wet",
          fmt::format("surface waves dry, none wet, Gamma in [3, 5] (f = {:g} Hz)", lf.f0),
          "surface waves (most seeds): dry at Gamma = " + (seen[0].empty() ? "none" : seen[0]) +
              "; wet at Gamma = " + (seen[1].empty() ? "none" : seen[1]),
          qualified(!any_wave_point         ? "not tested (no Gamma in [3, 5] classified for both)"
                    : dry_waves && wet_none ? "yes"
                                            : "no",
                    lf.unclassified(-1, mid))};
}

// "At Gamma ~ 5, both dry and wet granular layers crystallize again" as f increases.
FeatureCheck crystalAgainCheck(const LowestFrequency& lf, SolidCriterion c) {
  const StabilityGrid& grid = lf.grid;
  const std::string key = std::string("crystal_again_at_gamma_5") + criterionKey(c);
  const std::string feature = std::string(
                                  "both layers crystallize again at Gamma = 5 as f "
                                  "increases (") +
                              criterionName(c) + ")";
  const auto g5 = std::find(grid.gammas.begin(), grid.gammas.end(), 5.0);
  if (g5 == grid.gammas.end() || grid.frequencies.size() < 2)
    return {key, feature, "–", "not tested (Gamma = 5 or a second frequency not on the grid)"};
  const std::size_t j5 = static_cast<std::size_t>(g5 - grid.gammas.begin());
  const double f_top = *std::max_element(grid.frequencies.begin(), grid.frequencies.end());
  std::string where;
  bool at_top = false, top_classified = false;
  for (std::size_t i = 0; i < grid.frequencies.size(); ++i) {
    const LayerVerdict &a = grid.at(0, i, j5), &b = grid.at(1, i, j5);
    if (grid.frequencies[i] == f_top) top_classified = a.classified() && b.classified();
    const bool both = a.classified() && b.classified() && a.stateBy(c).value == "crystal" &&
                      b.stateBy(c).value == "crystal";
    if (!both || grid.frequencies[i] <= lf.f0) continue;
    where += (where.empty() ? "" : ", ") + formatCompact(grid.frequencies[i]) + " Hz";
    at_top |= grid.frequencies[i] == f_top;
  }
  return {key, feature, "both crystals at Gamma = 5: " + (where.empty() ? "nowhere" : where),
          at_top           ? "yes (at the highest f)"
          : top_classified ? "no"
                           : "not tested (Gamma = 5 at the highest f not classified)"};
}

// A smaller share of differing points among the comparable ones (both laws classified) at
// every higher f than at the lowest; nothing to shrink without a difference at the lowest f,
// nothing to compare at a frequency without comparable points.
FeatureCheck differencesShrinkCheck(const LowestFrequency& lf, SolidCriterion c) {
  const StabilityGrid& grid = lf.grid;
  const std::size_t NF = grid.frequencies.size(), i0 = lf.i0;
  const std::vector<double> n = grid.symbolDifferencesPerFrequency(c);
  std::vector<double> comparable(NF, 0);
  for (std::size_t i = 0; i < NF; ++i)
    for (std::size_t j = 0; j < grid.gammas.size(); ++j)
      comparable[i] += grid.at(0, i, j).classified() && grid.at(1, i, j).classified();
  bool shrinking = n[i0] > 0, all_comparable = true;
  std::string per_f;
  for (std::size_t i = 0; i < NF; ++i) {
    all_comparable &= comparable[i] > 0;
    if (grid.frequencies[i] > lf.f0 && comparable[i] > 0 && comparable[i0] > 0)
      shrinking &= n[i] / comparable[i] < n[i0] / comparable[i0];
    per_f += fmt::format("{}{:g} Hz: {:g} of {:g}", i ? ", " : "", grid.frequencies[i], n[i],
                         comparable[i]);
  }
  return {std::string("differences_shrink_with_f") + criterionKey(c),
          std::string("dry-wet differences (state, surface waves, kinks) smaller at higher f (") +
              criterionName(c) + ")",
          "points that differ, of those classified for both laws: " + per_f,
          NF < 2            ? "not tested (one frequency)"
          : !all_comparable ? "not tested (a frequency without classified points)"
          : shrinking       ? "yes"
                            : "no"};
}

}  // namespace

std::vector<FeatureCheck> checkPaperFeatures(const StabilityGrid& grid) {
  const LowestFrequency lf(grid);
  std::vector<FeatureCheck> out;
  for (SolidCriterion c : kSolidCriteria)
    for (int law = 0; law < kLaws; ++law) fluidizationChecks(lf, law, c, out);
  out.push_back(surfaceWaveCheck(lf));
  for (SolidCriterion c : kSolidCriteria) {
    out.push_back(crystalAgainCheck(lf, c));
    out.push_back(differencesShrinkCheck(lf, c));
  }
  return out;
}

std::size_t lowestFrequency(const StabilityGrid& grid) { return LowestFrequency(grid).i0; }

}  // namespace granwave
