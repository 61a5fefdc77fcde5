#pragma once
// Per-particle dynamic state, advanced lazily: each particle carries the time `t` its
// stored position and velocity refer to. Between events it flies ballistically under
// gravity, or rides a wall: it is carried rigidly with the bottom or the lid (z = z_b(t) +
// offset) while that wall pushes it, directly or through other riding particles.
#include <cstdint>
#include <vector>

namespace granwave {

enum class Motion : std::uint8_t { Ballistic, RideBottom, RideLid };

struct ParticleState {
  // Hot: read for every neighbour in every prediction (first 64-byte line).
  double x = 0, z = 0;        // m
  double vx = 0, vz = 0;      // m/s
  double t = 0;               // s, time of the stored position/velocity
  double ride_offset = 0;     // m, z - z_b(t) while riding (rigidly carried by the wall)
  std::uint32_t counter = 0;  // collisions and motion changes, for lazy invalidation
  Motion motion = Motion::Ballistic;
  // Consecutive collisions in enduring contact (each within t_c of the previous one, slower
  // than the sleep speed, with no flying particle below): the sleep rule (docs/physics.md,
  // "Resting contacts", item 7).
  std::uint16_t rattle = 0;
  // Cold: only at this particle's own collisions.
  double omega = 0;                // rad/s about y
  double last_collision = -1e300;  // s, for the TC model
  double burst_start = -1e300;     // collapse detection window
  std::uint32_t burst = 0;         // collisions in the current window
  // Collisions in a row, each within t_c of the previous one (the TC model's enduring
  // contact), counted while the sleep rule waits for its alarm (docs/physics.md, "Resting
  // contacts", item 7).
  std::uint32_t enduring = 0;
};

// Initial condition handed to the engine (lab frame, t = 0).
struct InitialCondition {
  std::vector<double> x, z, vx, vz, omega;
  int size() const { return static_cast<int>(x.size()); }
};

}  // namespace granwave
