#pragma once
// The outputs of one cached run as the studies use them, read back from the run's files:
// phase-averaged particle fields (FIELDS.h5, docs/fields.md), the observables of the H5MD run
// file, the LAMMPS deck's centre of mass, and (HydroRunFile.hpp) the hydro solver's fields
// (HYDRO.h5, docs/hydro.md).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace granwave {

struct Front {
  int first_phase = 0;                 // index of the first phase in the window
  int last_phase = 0;                  // index of the last (cyclic: may be below the first)
  double start = 0;                    // t/T of the first phase, within the window
  double speed = 0, error = 0;         // m/s, lab frame
  double peak = 0;                     // max T~_g / T0 over the episode
  double gas_ahead = 0, relative = 0;  // m/s (particles only)
  bool from_impact = true;
};

// Profiles laid out [phase][z]; block profiles [block][phase][z].
struct Profiles {
  int phases = 0, nz = 0;
  std::vector<double> z;                         // m, lab-frame cell centres
  std::vector<double> phase, plate, com, front;  // t/T within the window; m
  std::vector<double> temperature, area_fraction, velocity_z, rms_velocity_x;
  double at(const std::vector<double>& field, int phase, int j) const {
    return field[static_cast<std::size_t>(phase) * nz + j];
  }
  // Phase index nearest to t/T, the window taken as periodic.
  int phaseIndex(double t_over_T) const;
};

struct ParticleFields : Profiles {
  double T0 = 0, diameter = 0, mass = 0, frequency = 0, amplitude = 0;
  int cycles_per_window = 0, layer_period = 0, pooled_cycles = 0, blocks = 0;
  std::vector<double> block_temperature, block_area_fraction, block_velocity_z, block_rms_vx;
  std::vector<Front> fronts;
};

struct HydroFields : Profiles {
  int period = 0, cycles = 0, cells = 0;
  bool periodic = false;
  std::int64_t steps = 0, rhs_evals = 0;
  double rtol = 0, cpu_seconds = 0;
  std::string regime;  // hydro::regimeName: fluidised, moves as a solid, or at rest
  std::vector<Front> fronts;
};

struct RunObservables {
  std::vector<double> time, com_height, kinetic_energy;
  std::vector<double> pair_impact_energy, pair_impact_loss;       // cumulative, J
  std::vector<double> pair_count, tc_elastic_count;               // cumulative, per record
  std::uint64_t events = 0, pair_collisions = 0, tc_elastic = 0;  // at the end
  std::uint64_t wall_collisions = 0;                              // at the end
};

// The live classification of a particle run (FIELDS.h5 /patterns, docs/classification.md).
struct LayerPatterns {
  bool available = false;
  std::string state;  // "crystal", "amorphous", "liquid-like"
  bool surface_wave = false;
  int surface_wave_mode = 0, kinks = 0, period = 0;
  double surface_wave_amplitude_d = 0, psi6 = 0, mobility_d = 0, bonds_kept = 1;
  double bonds_kept_per_cycle = 1;
  // The within-cycle criterion (coarse_grain/WithinCycleState.hpp): its label, the mean
  // neighbours and <|psi6|> at each cycle's most compact phase, and the particles on the lid.
  std::string within_cycle_state;
  double within_cycle_coordination = 0, within_cycle_psi6 = 0, lid_row = 0;
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

// The layer's state window by window (FIELDS.h5 /period_doubling and /states;
// docs/classification.md, "Layer state over time").
struct StateSeries {
  bool available = false;
  int window_cycles = 12, period2_windows = 0;
  int layer_period = 0;                                     // the run's period (runPeriod)
  double period2_share = 0, share_low = 0, share_high = 1;  // 95 % Wilson, n_eff
  double effective_windows = 0;
  std::vector<double> f2_strength, threshold;
  int state_windows[2] = {-1, -1};  // windows the state-conditioned fields pooled (-1: none)
  int windows() const { return static_cast<int>(f2_strength.size()); }
};

ParticleFields readParticleFields(const std::string& fields_path);
// The fields of the period-1 or period-2 episodes alone (FIELDS.h5 /states/periodN), if the
// run had enough windows in that state.
std::optional<ParticleFields> readStateFields(const std::string& fields_path, int period);
StateSeries readStateSeries(const std::string& fields_path);
LammpsTrajectory readLammpsTrajectory(const std::string& path);
LayerPatterns readLayerPatterns(const std::string& fields_path);
Frame readLastFrame(const std::string& run_path);
RunObservables readRunObservables(const std::string& run_path);

}  // namespace granwave
