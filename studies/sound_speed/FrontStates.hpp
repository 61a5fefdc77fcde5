#pragma once
// The state of the layer just ahead of (above) and just behind (below) a moving front, read
// from phase-averaged profiles: rows `gap` to `gap + rows - 1` diameters away from the front's
// row on either side, area-fraction weighted, averaged over the phases of the front's episode.
#include <vector>

#include "coarse_grain/PhaseProfiles.hpp"

namespace granwave {

struct GasSample {
  double nu = 0, T = 0, uz = 0;  // area fraction, J, m/s (lab)
  bool valid = false;            // some row on that side had particles
};

struct FrontStates {
  GasSample ahead, behind;
  int phases = 0;
};

// Phases of the episode starting at `first_phase` (index): consecutive phases (cyclic) with a
// front height. `field_block` < 0 uses the pooled profiles, else that block's.
std::vector<int> episodePhases(const PhaseProfiles& p, int first_phase);
FrontStates frontStates(const PhaseProfiles& p, const std::vector<int>& phases, int rows, int gap,
                        int block = -1);

}  // namespace granwave
