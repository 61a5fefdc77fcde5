#pragma once
// Plain state of all particles at one recording time, handed to observers (recorders,
// coarse-graining, progress). Positions are lab-frame centres in the x-z plane; omega is
// the angular velocity about y (all zero when friction is off).
#include <cstdint>
#include <vector>

namespace granwave {

struct CollisionCounts {
  std::uint64_t pair = 0;        // particle-particle collisions
  std::uint64_t wall = 0;        // particle-wall collisions (bottom, lid, sides)
  std::uint64_t tc_elastic = 0;  // of these, made elastic by the TC model
  std::uint64_t rests = 0;       // wall contacts that ended at rest on the wall (riding)
};

struct Observables {
  double center_of_mass_height = 0;  // m, lab frame
  double kinetic_energy = 0;         // J, translational
  double rotational_energy = 0;      // J
  double potential_energy = 0;       // J, m g z summed
  double dissipated_energy = 0;      // J, cumulative loss in collisions (partner/wall frame)
  // J, the part of dissipated_energy lost in collisions with the walls (plate, lid and side
  // walls; the energy budget of the layer: docs/physics.md). A particle the resting-contact
  // rule puts to rest on the plate counts in dissipated_energy only.
  double wall_dissipated_energy = 0;
  double wall_work = 0;  // J, cumulative work done by moving walls
  double pressure = 0;   // Pa m (2D), collisional+kinetic, periodic boxes only
  // Cumulative normal impact energy (m/4) v_n^2 of the pair collisions that used the
  // restitution law (TC-elastic ones excluded), and its part lost, (m/4) (1 - e_n^2) v_n^2.
  // Their ratio is the energy-weighted <1 - e_n^2> of the run: e_eff^2 = 1 - loss/impact,
  // the particle-level counterpart of hydro's Phi_W (effective-restitution study).
  double pair_impact_energy = 0;  // J
  double pair_impact_loss = 0;    // J
  CollisionCounts collisions;
  std::uint64_t events = 0;  // all processed events (collisions, crossings, ...)
};

struct Snapshot {
  std::uint64_t step = 0;   // recording index
  double time = 0;          // s
  double plate_height = 0;  // m, z_b(t)
  std::vector<double> x, z, vx, vz, omega;
  Observables obs;
  int size() const { return static_cast<int>(x.size()); }
};

// Read-only consumer of recordings (HOOMD's Analyzer): never changes the simulation.
class SnapshotObserver {
 public:
  virtual ~SnapshotObserver() = default;
  virtual void observe(const Snapshot& snapshot) = 0;
};

}  // namespace granwave
