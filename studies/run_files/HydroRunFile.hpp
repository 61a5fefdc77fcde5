#pragma once
// The hydro run file HYDRO.h5 (layout in docs/hydro.md, "Output"): written by `granwave hydro`
// and read back by the studies, both here, so the format has one owner.
#include <cstdint>
#include <string>
#include <vector>

#include "coarse_grain/WaveFront.hpp"
#include "studies/run_files/RunOutputs.hpp"

namespace granwave {

// What one `granwave hydro` run wrote, laid out as in the file. Fields are [phase][cell]
// (plate frame, `cells` cells) or [phase][row] (lab frame, the coarse-graining grid's rows).
struct HydroRunContent {
  std::size_t phases = 0, cells = 0, rows = 0;
  std::vector<double> plate_z;  // m: [phase][cell] cell centres above the plate (they move)
  std::vector<double> lab_z;    // m: the lab-frame rows
  std::vector<double> number_density, velocity_z, temperature, area_fraction, pressure;
  std::vector<double> lab_area_fraction, lab_temperature, lab_velocity_z;
  std::vector<double> time, plate_height, center_of_mass_height;  // per phase, s and m
  std::vector<double> front_height, front_peak_temperature;       // per phase, m and T/T0
  std::vector<FrontEpisode> fronts;
  double rtol = 0;
  std::int64_t cycles = 0, period = 0, steps = 0, rhs_evals = 0, jacobian_evals = 0;
  std::int64_t error_test_failures = 0, nonlinear_failures = 0;
  bool periodic = false;
  std::string regime;  // hydro::regimeName: at rest, solid or fluidised
  double cpu_seconds = 0;
  std::string scene_toml;  // the fully resolved scene
};

// The file's root attribute "format": its name and layout version.
inline constexpr const char* kHydroRunFormat = "granwave-hydro-1";

// Atomic: the file appears complete or not at all.
void writeHydroRunFile(const std::string& path, const HydroRunContent& content);

// The lab-frame profiles, fronts and solver figures as the studies use them.
HydroFields readHydroFields(const std::string& hydro_path);

}  // namespace granwave
