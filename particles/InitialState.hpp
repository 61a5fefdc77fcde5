#pragma once
// Initial condition of a scene (docs/physics.md; the paper's Methods): random
// non-overlapping positions (random sequential addition, seeded) or a lattice; velocities
// either the paper's (random directions, speeds uniform below 1e-2 sqrt(g d)) or Maxwellian
// at the scene's temperature (mean kinetic energy per particle, exactly, with zero total
// momentum). Spins start at zero.
#include "particles/EdSimulation.hpp"
#include "scene/Scene.hpp"

namespace granwave {

InitialCondition initialCondition(const Scene& scene, const EngineConfig& config);

}  // namespace granwave
