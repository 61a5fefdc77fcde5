#pragma once
// Phase-averaged continuum fields from pooled particle sums (paper Sec. IV;
// docs/fields.md, "Definitions"), for one block of cycles or all of them:
//   n(i,j)        pooled count; area fraction nu = (n / snapshots) (pi d^2/4) / (w_x w_z)
//   v~(i,j)       mean velocity of the pooled particles
//   T_g(i,j)      m sum_k (v_k - v~)^2 / (2 n): fluctuation kinetic energy per particle
//   T_rot(i,j)    I sum_k (w_k - w~)^2 / (2 n)
// valid only where n >= min_count (the paper's n >= 3). Profiles per row j:
//   T~_g(z_j)  = <T_g(i,j)>_i,   v~_z(z_j) = <v~_z(i,j)>_i   over valid cells;
//   RMS(v_x)(z_j) = sqrt(<(v~_x(i,j) - <v~_x>_i)^2>_i)   (the square root is meant: see
//   docs/fields.md);  nu(z_j) = <nu(i,j)>_i over all cells; centre-of-mass height.
#include <limits>
#include <vector>

#include "coarse_grain/PhaseAccumulator.hpp"

namespace granwave {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct FieldParams {
  double mass = 0, inertia = 0, diameter = 0;
  int min_count = 3;
};

// Arrays are [phase][z][x] (fields) or [phase][z] (profiles), NaN where not valid.
struct PhaseFields {
  int phases = 0, nz = 0, nx = 0;
  std::vector<double> count, area_fraction, velocity_x, velocity_z, temperature,
      rotational_temperature;
  std::vector<double> profile_temperature, profile_velocity_z, profile_rms_velocity_x,
      profile_area_fraction;
  std::vector<double> center_of_mass_height;  // [phase], m
  std::vector<double> snapshots;              // [phase], snapshots pooled
  // [phase], J: the energy that crossed the layer's budget over the recorded interval ending
  // at the phase (the moving walls' work; the loss in pair collisions, with that of particles
  // put to rest; the loss in collisions with the plate, lid and side walls),
  // mean over the pooled windows; empty when not recorded (the continuum keeps its own).
  std::vector<double> plate_work, pair_loss, wall_loss;

  std::size_t cell(int phase, int j, int i) const {
    return (static_cast<std::size_t>(phase) * nz + j) * nx + i;
  }
  std::size_t row(int phase, int j) const { return static_cast<std::size_t>(phase) * nz + j; }
};

// block = -1: all blocks pooled.
PhaseFields computeFields(const PhaseAccumulator& acc, const FieldParams& params, int block = -1);

}  // namespace granwave
