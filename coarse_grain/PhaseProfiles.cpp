#include "coarse_grain/PhaseProfiles.hpp"

#include <algorithm>
#include <cmath>

namespace granwave {

int PhaseProfiles::phaseIndex(double t) const {
  // Circular distance: the window repeats (it holds whole cycles of the periodic state).
  const int n = phases();
  const double window = n > 1 ? n * (phase[1] - phase[0]) : 1.0;
  auto distance = [&](int p) {
    const double d = std::fmod(std::abs(phase[p] - t), window);
    return std::min(d, window - d);
  };
  int best = 0;
  for (int p = 1; p < n; ++p)
    if (distance(p) < distance(best)) best = p;
  return best;
}

PhaseFields profilesOf(const PhaseFields& f) {
  PhaseFields p;
  p.phases = f.phases;
  p.nz = f.nz;
  p.nx = f.nx;
  p.profile_temperature = f.profile_temperature;
  p.profile_velocity_z = f.profile_velocity_z;
  p.profile_rms_velocity_x = f.profile_rms_velocity_x;
  p.profile_area_fraction = f.profile_area_fraction;
  p.center_of_mass_height = f.center_of_mass_height;
  p.snapshots = f.snapshots;
  p.plate_work = f.plate_work;
  p.pair_loss = f.pair_loss;
  p.wall_loss = f.wall_loss;
  return p;
}

}  // namespace granwave
