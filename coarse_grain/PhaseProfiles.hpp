#pragma once
// The layer over one window of drive phases, row by row in the lab frame: the profiles of the
// pooled cycles and of each block of cycles, the plate, centre-of-mass and front heights at each
// phase, and the front episodes. The fields file holds this of the particles (FieldsLayout.hpp)
// and the hydro run file the same of the continuum on the same rows, so the two are compared
// through one type.
#include <vector>

#include "coarse_grain/PhaseFields.hpp"
#include "coarse_grain/WaveFront.hpp"

namespace granwave {

struct PhaseProfiles {
  std::vector<double> z;                       // m, the rows' centres (FieldGrid::zCentre)
  std::vector<double> time;                    // [phase] s since the window's start
  std::vector<double> phase;                   // [phase] t/T within the window
  std::vector<double> plate_height;            // [phase] m
  std::vector<double> front_height;            // [phase] m, NaN where there is no front
  std::vector<double> front_peak_temperature;  // [phase] peak T~_g / T0
  // The profiles (profile_*, [phase][z]) and center_of_mass_height; the cell arrays stay empty.
  // A profile a model has no data for (the continuum's RMS(v_x)) is empty where the window is
  // made and NaN where it is read from a file (FieldsReader.hpp).
  PhaseFields pooled;
  std::vector<PhaseFields> blocks;   // the same per block of cycles (empty for the continuum)
  std::vector<FrontEpisode> fronts;  // without their per-phase time and height

  int phases() const { return pooled.phases; }
  int rows() const { return pooled.nz; }
  double at(const std::vector<double>& profile, int phase, int row) const {
    return profile[pooled.row(phase, row)];
  }
  // Phase index nearest to t/T, the window taken as periodic.
  int phaseIndex(double t_over_T) const;
  // t/T at which an episode starts.
  double start(const FrontEpisode& e) const {
    return phase[static_cast<std::size_t>(e.first_phase)];
  }
};

// The profiles of `fields` without its cells (the copy the profiles of a window keep).
PhaseFields profilesOf(const PhaseFields& fields);

}  // namespace granwave
