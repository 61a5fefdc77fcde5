#pragma once
// Phase averaging of a driven run, live (an observer of the engine) or offline (fed the
// frames of a run file): every record is a phase t/T mod 1 (M per cycle); records are pooled
// over the steady cycles at the same phase of a window of P cycles (P = 2 keeps the two
// impacts of a period-doubled layer apart). The transient is discarded: until the steady-
// state detector fires (or a fixed number of cycles), nothing is pooled. Steady cycles are
// split into `blocks` consecutive blocks for uncertainties.
#include "coarse_grain/PhaseAccumulator.hpp"
#include "coarse_grain/SteadyStateDetector.hpp"
#include "particles/Checkpointable.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

struct PhaseAveragerConfig {
  FieldGrid grid;
  int samples_per_cycle = 100;  // M
  int cycles_per_window = 2;    // P
  int blocks = 5;
  int total_cycles = 0;    // whole cycles the run will have
  int fixed_discard = -1;  // >= 0: discard this many cycles instead of detecting
  SteadyStateOptions steady;
};

class PhaseAverager : public SnapshotObserver, public Checkpointable {
 public:
  explicit PhaseAverager(const PhaseAveragerConfig& config);
  void observe(const Snapshot& s) override;
  void saveState(h5::File& file, const std::string& group) const override;
  void restoreState(const h5::File& file, const std::string& group) override;

  const PhaseAccumulator& accumulator() const { return acc_; }
  const PhaseAveragerConfig& config() const { return cfg_; }
  // First pooled cycle (= cycles discarded), -1 if the run never became steady.
  int firstPooledCycle() const { return start_cycle_; }
  int pooledCycles() const { return pooled_cycles_; }

 private:
  void endOfCycle(int cycle);
  PhaseAveragerConfig cfg_;
  PhaseAccumulator acc_;
  SteadyStateDetector detector_;
  int start_cycle_ = -1;
  int cycles_per_block_ = 1;
  int pooled_cycles_ = 0;
  int current_cycle_ = -1;
  double cycle_height_sum_ = 0;
  int cycle_samples_ = 0;
  // The cumulative budget of the last record (wall work, pair loss, wall loss; J), whose
  // increments are pooled; `has_last_` false before the first record.
  double last_budget_[PhaseAccumulator::kBudgetTerms] = {0, 0, 0};
  bool has_last_ = false;
};

}  // namespace granwave
