#pragma once
// The stability study's grid of verdicts: for each law (dry, wet), frequency f and Gamma, the
// seeds' verdict on the particle layer (SeedVote.hpp). Shared by the study's diagrams and its
// check of the paper's features (StabilityFeatures.hpp).
#include <cstddef>
#include <string>
#include <vector>

#include "studies/stability/SeedVote.hpp"

namespace granwave {

// A dry-wet difference in one symbol of the paper's diagram (Fig. 3) or in any of them, the
// state by either solid criterion.
enum class Difference { state, state_within_cycle, surface_waves, kinks, any, any_within_cycle };
inline constexpr Difference kDifferences[6] = {
    Difference::state, Difference::state_within_cycle, Difference::surface_waves, Difference::kinks,
    Difference::any,   Difference::any_within_cycle};
// Key in results.h5 ("state", "state_within_cycle", "waves", "kinks", "any", "any_within_cycle")
// and its name in the report.
const char* differenceKey(Difference d);
const char* differenceName(Difference d);

struct StabilityGrid {
  std::vector<double> frequencies, gammas;  // Hz, 1
  std::vector<LayerVerdict> verdicts[2];    // [law][i_f * gammas.size() + j_gamma]

  const LayerVerdict& at(int law, std::size_t i, std::size_t j) const {
    return verdicts[law][i * gammas.size() + j];
  }
  // Dry and wet differ in a symbol of the paper's diagram (Fig. 3: the state, surface waves,
  // kinks), by the seeds' verdicts, the state by `criterion`. False where either law has no
  // classified run.
  bool symbolsDiffer(std::size_t i, std::size_t j,
                     SolidCriterion criterion = SolidCriterion::bonds) const;
  // Dry and wet differ in `d`; false where either law has no classified run.
  bool differ(std::size_t i, std::size_t j, Difference d) const;
  // The number of Gamma points per frequency where they differ in `d`.
  std::vector<double> differencesPerFrequency(Difference d) const;
  // Dry and wet differ in the centre-of-mass period (modal over the seeds).
  bool periodsDiffer(std::size_t i, std::size_t j) const;
  // The number of Gamma points per frequency where symbolsDiffer (resp. periodsDiffer).
  std::vector<double> symbolDifferencesPerFrequency(
      SolidCriterion criterion = SolidCriterion::bonds) const;
  std::vector<double> periodDifferencesPerFrequency() const;
};

}  // namespace granwave
