#pragma once
// The summaries' `velocity front` lines (docs/commands.md): one per impact front of the
// velocity-jump tracker on a window's profiles (those with at least min_points tracked phases,
// or crossing a packed bottom within a phase): its start, its fitted speed and its transits
// between mass fractions 0.1, 0.5 and 0.9 (coarse_grain/FrontTransit.hpp). Used by `simulate
// --fields` and `fields` (FieldsSetup) and by `hydro`. Empty when the window has fewer than two
// phases.
#include <string>

#include "coarse_grain/PhaseProfiles.hpp"

namespace granwave {

std::string velocityFrontLines(const PhaseProfiles& profiles);

}  // namespace granwave
