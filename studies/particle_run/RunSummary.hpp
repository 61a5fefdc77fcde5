#pragma once
// The human-readable summary of a particle run (stdout of `granwave simulate`).
#include <string>
#include <vector>

#include "coarse_grain/PeriodDetector.hpp"
#include "coarse_grain/PeriodDoublingSeries.hpp"
#include "particles/Snapshot.hpp"
#include "scene/Scene.hpp"

namespace granwave {

struct RunSummaryInput {
  const Scene* scene = nullptr;
  std::string scene_name;
  Observables final_obs;  // counters at the end
  double simulated = 0;   // s
  double wall = 0;        // s
  double tc = 0;          // s
  // When the sleep rule's alarm switched it on (s; negative: it did not).
  double sleep_alarm_time = -1;
  bool completed = true;
  std::vector<double> com_height;   // one per record (driven: M per cycle)
  double energy_balance_error = 0;  // J, |E - E0 - W + D|
  double initial_energy = 0;
  // Checkpoints written by this process and the wall time they took (timing lines only).
  int checkpoints = 0;
  double checkpoint_wall = 0;  // s
};

// Period of the centre-of-mass motion, if the run is driven and long enough (12 cycles
// after the discarded transient): runPeriod, the rule `fields` uses too.
bool summarisePeriod(const RunSummaryInput& in, PeriodResult& out, int& discarded);

// The run's period-2 state window by window over the same steady part (PeriodDoublingSeries),
// if the run is driven and long enough.
bool summarisePeriodDoubling(const RunSummaryInput& in, PeriodDoublingSeries& out);

// "period-2 state   in 4 of 12 windows of 12 cycles (share 0.33, 95 % interval 0.12-0.65,
// 5.1 effective windows), 2 switches"
std::string formatPeriodDoubling(const PeriodDoublingSeries& s);
// With include_timing = false the wall-clock lines are left out: that version is stored in
// the run file, which must be bit-identical for the same scene and seed.
std::string formatRunSummary(const RunSummaryInput& in, bool include_timing = true);

}  // namespace granwave
