#pragma once
// The stability study (docs/studies.md; the paper's Fig. 3): dry and wet layers over drive
// frequency f and acceleration Gamma, each scene run past its transient and classified live
// (period, surface waves, kinks, crystal / amorphous / liquid-like), drawn as two diagrams
// with the dry-wet differences marked, beside the hydro solver's period and failures on the
// same grid, a snapshot gallery, and the paper's qualitative features checked one by one.
#include <memory>

#include "studies/framework/Study.hpp"

namespace granwave {

std::unique_ptr<Study> makeStabilityStudy(StudyFile& file);

}  // namespace granwave
