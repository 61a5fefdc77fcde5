#pragma once
// Momentum-transfer deficiency between a dry and a wet run with the same driving (paper
// Sec. V, Figs. 7-8): r_x(z, t) = RMS(v_x)_dry / RMS(v_x)_wet, and its row mean
// r~_x(t) = <r_x(z_j, t)>_j over rows where both are defined. A binary-collision argument
// gives about 2; the paper measures 2.17 +- 0.56 during the internal wave.
#include <vector>

#include "coarse_grain/PhaseFields.hpp"

namespace granwave {

struct Deficiency {
  int phases = 0, nz = 0;
  std::vector<double> ratio;     // [phase][z], NaN where undefined
  std::vector<double> row_mean;  // [phase]
  // Mean and standard deviation of row_mean over the selected phases (e.g. the wave).
  double mean = kNaN, std_dev = kNaN;
  int phases_used = 0;
};

// `select` (size = phases, may be empty = all) marks the phases to summarise; `min_rms`
// (m/s) excludes rows where the wet RMS is too small to divide by.
Deficiency momentumDeficiency(const PhaseFields& dry, const PhaseFields& wet,
                              const std::vector<bool>& select = {}, double min_rms = 1e-3);

// The ratio as the studies take it from two layers' profiles. Rows where either layer's
// pooled area fraction is below `min_area_fraction` are left out (a dilute row's RMS is a few
// particles'), and the dry layer is read `dry_shift` phases after the wet one (0: the same
// plate phase, the paper's definition; a shift aligns the two layers' impacts instead).
struct DeficiencyOptions {
  std::vector<bool> select;  // as above
  double min_rms = 1e-3;     // m/s, as above
  double min_area_fraction = 0;
  int dry_shift = 0;
};

// `dry` and `wet` are the pooled profiles (their area fractions decide the rows); the RMS(v_x)
// compared is theirs, or that of `dry_block` and `wet_block` (one block of cycles of each).
Deficiency momentumDeficiency(const PhaseFields& dry, const PhaseFields& wet,
                              const DeficiencyOptions& options,
                              const PhaseFields* dry_block = nullptr,
                              const PhaseFields* wet_block = nullptr);

}  // namespace granwave
