#pragma once
// The continuum's solution, computed in the plate frame on cells that move with the mass, seen
// in the lab frame on the rows of the particles' coarse-graining grid (coarse_grain/
// FieldGrid.hpp), where the same front detection as `granwave fields` runs on it. This is the
// form in which the studies compare it with the particles.
#include <vector>

#include "coarse_grain/FieldGrid.hpp"
#include "coarse_grain/PhaseProfiles.hpp"
#include "hydro/HydroSimulation.hpp"
#include "scene/Scene.hpp"
#include "scene/SceneDerived.hpp"

namespace granwave {

// One phase's plate-frame profiles (cell centres z, moving with the mass) on the lab rows,
// appended to the three vectors: linear between cell centres, the outermost cells' values out
// to the layer's edges, and no particles (area fraction 0, NaN temperature and velocity)
// outside the layer or the container. T = m theta (the particles' T_g); the velocity is the
// lab frame's, the plate's `plate_velocity` added.
void mapToLab(const hydro::HydroPhase& phase, double container_height, const FieldGrid& grid,
              double plate_velocity, double mass, std::vector<double>& area_fraction,
              std::vector<double>& temperature, std::vector<double>& velocity_z);

// The window of a run in the lab frame: profiles, phases (t/T = k/M, k = 1 .. P M: the
// window holds whole cycles), plate and centre-of-mass heights, and the fronts.
PhaseProfiles labFrameProfiles(const Scene& scene, const SceneDerived& derived,
                               const hydro::HydroResult& result, int samples_per_cycle);

}  // namespace granwave
