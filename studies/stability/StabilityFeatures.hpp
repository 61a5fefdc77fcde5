#pragma once
// The paper's qualitative stability features (Huang, Sec. III, Fig. 3), each checked on the
// stability study's grid of seed verdicts and answered "yes", "no" or "not tested":
//   - at the lowest f both layers are fluid for Gamma in [3, 5] and solid at Gamma = 2;
//   - at the lowest f both are solid again at Gamma >= 6 (compression by the lid);
//   - at the lowest f the dry layer shows surface waves for Gamma in [3, 5], the wet one none;
//   - both layers are crystals again at Gamma = 5 at the highest f;
//   - the dry-wet differences in the diagram's symbols shrink as f rises.
// Every check that involves the state is made twice, once per solid criterion (SeedVote.hpp):
// keys without suffix for the bond criterion, with "_within_cycle" for the other.
#include <cstddef>
#include <string>
#include <vector>

#include "studies/stability/StabilityGrid.hpp"

namespace granwave {

struct FeatureCheck {
  std::string key;       // short name in results.h5 (/results/stability/features)
  std::string feature;   // the paper's statement
  std::string observed;  // what this grid shows
  std::string verdict;   // "yes", "no", or "not tested (...)"
};

std::vector<FeatureCheck> checkPaperFeatures(const StabilityGrid& grid);

// Index of the grid's lowest frequency (where the first three features are stated).
std::size_t lowestFrequency(const StabilityGrid& grid);

}  // namespace granwave
