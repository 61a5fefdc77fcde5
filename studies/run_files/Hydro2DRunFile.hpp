#pragma once
// The 2D hydro run file (`granwave hydro` with hydro.dimensions = 2; layout in docs/hydro.md,
// "The 2D model") and its XDMF sidecar, which ParaView opens: the layer's cells as
// quadrilaterals that move with the mass (each column's cells between its node heights), with
// the fields cell-centred, one grid per recorded phase. The format has one owner: this file.
#include <cstdint>
#include <string>
#include <vector>

#include "coarse_grain/SurfaceWaveSpectrum.hpp"
#include "studies/run_files/EnergyBudgetGroup.hpp"

namespace granwave {

struct Hydro2DRunContent {
  std::size_t columns = 0, cells = 0;  // Nx, and N per column
  double width = 0;                    // m
  bool periodic = true;                // else between side walls
  // The window's phases (s from the run's start; m, plate and lab centre of mass).
  std::vector<double> time, plate_height, plate_velocity, center_of_mass_height;
  std::vector<double> node_z;  // m, plate frame: [phase][column][node], N + 1 nodes
  // [phase][column][cell]: area fraction, T = m theta (J), velocities (plate frame, m/s),
  // pressure (N/m).
  std::vector<double> area_fraction, temperature, velocity_x, velocity_z, pressure;
  std::vector<double> com_per_phase;  // every phase of the run, plate frame, m
  // The surface waves of the run's second half (/surface, coarse_grain/SurfaceWavesFile.hpp).
  SurfaceWaveAnalysis surface;
  int samples_per_cycle = 0;
  double rtol = 0, cpu_seconds = 0, mass_drift = 0;
  std::int64_t cycles = 0, steps = 0, rhs_evals = 0, linear_iterations = 0;
  std::int64_t preconditioner_jacobians = 0;
  std::int64_t remaps = 0;  // vertical remaps (hydro.remap_share)
  double remap_heat = 0;    // J per unit depth the remaps moved into heat, summed
  // The energy that crossed the layer over each phase of the window (J), when the scene asked
  // for it (hydro.energy_budget); empty otherwise.
  RunEnergyBudget budget;
  std::string scene_toml;  // the fully resolved scene
  std::size_t phases() const { return time.size(); }
  int windowCycles() const { return static_cast<int>(phases()) / samples_per_cycle; }
};

// The file's root attribute "format": its name and layout version.
inline constexpr const char* kHydro2DRunFormat = "granwave-hydro2d-1";

// The /solver group of a 2D run file: what the run cost and did (a run's cost table, the
// studies that read 2D runs).
struct Hydro2DSolverRecord {
  std::int64_t cycles = 0, steps = 0, rhs_evals = 0, remaps = 0;
  double cpu_seconds = 0, mass_drift = 0;
};
Hydro2DSolverRecord readHydro2DSolver(const std::string& path);

// Writes the HDF5 file and its sidecar (the same path with .xdmf), each atomically; the pair
// or neither (the HDF5 file is removed again if the sidecar cannot be written).
void writeHydro2DRunFile(const std::string& path, const Hydro2DRunContent& content);

}  // namespace granwave
