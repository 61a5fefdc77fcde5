#pragma once
// What the studies read of a finished particle run's H5MD file (through particles/
// H5mdReader), and the LAMMPS deck's output. The fields file is read by coarse_grain/
// FieldsReader.hpp, the hydro run file by HydroRunFile.hpp.
#include <cstdint>
#include <string>
#include <vector>

namespace granwave {

struct RunObservables {
  std::vector<double> time, com_height, kinetic_energy;
  std::vector<double> dissipated_energy;                          // cumulative, J
  std::vector<double> pair_impact_energy, pair_impact_loss;       // cumulative, J
  std::vector<double> pair_count, tc_elastic_count;               // cumulative, per record
  std::uint64_t events = 0, pair_collisions = 0, tc_elastic = 0;  // at the end
  std::uint64_t wall_collisions = 0;                              // at the end
};

// Particle positions of one recorded frame (lab frame, m).
struct Frame {
  std::vector<double> x, z;
  double plate = 0;
};

// The LAMMPS deck's output (studies/lammps/paper-scene.lmp): per sample the paper's time t,
// the plate height and the centre-of-mass height (m, lab frame).
struct LammpsTrajectory {
  std::vector<double> time, plate, com;
  double last_step = 0;
};

LammpsTrajectory readLammpsTrajectory(const std::string& path);
Frame readLastFrame(const std::string& run_path);
RunObservables readRunObservables(const std::string& run_path);

}  // namespace granwave
