#pragma once
// The numbers of the sound-speed study: for every impact front of the particle runs, the
// states ahead of and behind it, its speed relative to the gas ahead, and what each theory
// predicts for it; written under /results/sound_speed (docs/studies.md).
#include <array>
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "studies/contract/Study.hpp"
#include "studies/sound_speed/FrontStates.hpp"
#include "studies/sound_speed/SoundSpeedStudy.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

// The theories, in the order of /results/sound_speed/theory_<k>.
inline constexpr int kTheories = 6;
inline constexpr const char* kTheoryNames[kTheories] = {"adiabatic sound speed c_s",
                                                        "isothermal sound speed c_T",
                                                        "Rankine-Hugoniot shock",
                                                        "strong shock (cold gas ahead)",
                                                        "compaction front (close packing behind)",
                                                        "mass conservation (measured states)"};

// One impact front (or a run that gave none to compare: failed, or no state on a side).
struct FrontComparison {
  enum class Outcome { RunFailed, NoState, Compared } outcome = Outcome::Compared;
  std::string run, failure;
  double start = 0;  // t/T of the front's first phase within the window
  FrontStates states;
  double T0 = 0;                              // J, the run's temperature scale
  Measurement w;                              // m/s, relative to the gas ahead
  std::array<Measurement, kTheories> theory;  // invalid: the theory does not apply
  std::array<bool, kTheories> holds{};        // within 2 combined sigma
};

// Per theory, the fronts where it applies: prediction and measured w, with errors.
struct TheorySeries {
  std::vector<double> predicted, predicted_error, measured, measured_error;
  int tested = 0, holds = 0;
};

struct SoundSpeedResults {
  std::vector<FrontComparison> fronts;
  std::array<TheorySeries, kTheories> theories;
  std::vector<double> front_speed_relative, mach_number;  // of every compared front
};

SoundSpeedResults analyseSoundSpeed(const SoundSpeedConfig& config, const RunSet& runs);
void writeSoundSpeedResults(h5::File& file, const SoundSpeedResults& results);

}  // namespace granwave
