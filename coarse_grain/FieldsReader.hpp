#pragma once
// Reads a fields file back (layout in FieldsLayout.hpp; FieldsFile.hpp writes it): the window's
// profiles, phases and fronts (of the whole run or of one layer state), the run's parameters,
// the period-2 state window by window, and the live classification. The cells (/fields, /xdmf)
// are left on disk: the studies compare profiles. Every failure is an h5::H5Error naming the
// file and the object.
#include <optional>
#include <string>

#include "coarse_grain/FieldsAnalysis.hpp"
#include "coarse_grain/PhaseProfiles.hpp"
#include "h5/File.hpp"

namespace granwave {

// What a fields file holds of one window (the whole run's, or one layer state's).
struct FieldsRecord {
  // diameter, mass, frequency, amplitude, T0, layer_period, source, scene_toml, and (whole run
  // only) period_doubling, empty when the file has none; inertia is not stored.
  FieldsContext context;
  int samples_per_cycle = 0, cycles_per_window = 0, blocks = 0;
  int discarded_cycles = -1, pooled_cycles = 0;
  // Windows of 12 cycles counted in each layer state (-1: not measured; whole run only).
  int state_windows[2] = {-1, -1};
  int state_period = 0;  // 1 or 2 for a state's fields, 0 for the whole run
  PhaseProfiles profiles;
};

FieldsRecord readFieldsFile(const std::string& fields_path);
// The fields of the period-1 or period-2 windows alone (/states/periodN), if the run had
// enough windows in that state; context.layer_period is then that period.
std::optional<FieldsRecord> readStateFields(const std::string& fields_path, int period);

// The profiles, phases and fronts under `root` ("" or a state's root). A profile the file does
// not hold is NaN; so is a front column, except the speed's error, which hydro run files
// written before the names were shared hold as fit_error (FieldsLayout.hpp). /phases/phase and
// the lab-frame rows are read where those files kept them, or left empty.
PhaseProfiles readPhaseProfiles(const h5::File& file, const std::string& root);

// The live classification as /patterns stores it: labels, counts and means (not the positions
// of kinks or the surface profile), and the run's period.
struct LayerPatterns {
  bool available = false;
  std::string state;  // "crystal", "amorphous", "liquid-like"
  bool surface_wave = false;
  int surface_wave_mode = 0, kinks = 0, period = 0;
  double surface_wave_amplitude_d = 0, psi6 = 0, mobility_d = 0, bonds_kept = 1;
  double bonds_kept_per_cycle = 1;
  // The within-cycle criterion (WithinCycleState.hpp): its label, the mean neighbours and
  // <|psi6|> at each cycle's most compact phase, and the particles on the lid.
  std::string within_cycle_state;
  double within_cycle_coordination = 0, within_cycle_psi6 = 0, lid_row = 0;
};

LayerPatterns readLayerPatterns(const std::string& fields_path);

}  // namespace granwave
