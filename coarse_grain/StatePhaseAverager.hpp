#pragma once
// Phase averages conditioned on the layer's state (docs/classification.md, "Layer state over
// time"): a bistable layer (wet, f = 10 Hz, Gamma = 4) spends episodes in a period-1 and a
// period-2 state; averaging both together mixes two different impacts. This observer pools
// each window of `window_cycles` cycles (12) first on its own, then, once the window's f/2
// strength is known (f2Window, the same rule and the same windows as PeriodDoublingSeries),
// adds it to the sums of its state. Windows start at the series' first window (the first even
// cycle after the larger of 3 cycles, a fifth of the run and the steady-state detector's
// transient); if the detector fires later than that, at the next window of the same grid.
//
// Phase windows hold 2 cycles. A period-2 episode can have its strong impact on even or odd
// cycles; the first period-2 window fixes the reference (its f/2 Fourier coefficient) and a
// later window whose coefficient points the other way (negative real part of the product with
// the reference's conjugate) is added with its two cycles swapped, so the strong impacts of all
// episodes land on the same cycle of the window.
//
// Blocks for uncertainties: a state's k-th window goes to block k mod B (interleaved; windows
// are 12 cycles, longer than the layer's memory of an impact, but episodes last several
// windows, so the block spread is a lower bound when a state is rare).
#include <complex>
#include <string>
#include <vector>

#include "coarse_grain/PhaseAccumulator.hpp"
#include "coarse_grain/PhaseAverager.hpp"
#include "coarse_grain/SteadyStateDetector.hpp"
#include "particles/Checkpointable.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

class StatePhaseAverager : public SnapshotObserver, public Checkpointable {
 public:
  // `config`: as for the whole-run averager (grid, M, blocks, total_cycles); its P is replaced
  // by 2 and its fixed_discard is not used.
  explicit StatePhaseAverager(const PhaseAveragerConfig& config, int window_cycles = 12);
  void observe(const Snapshot& s) override;
  void saveState(h5::File& file, const std::string& group) const override;
  void restoreState(const h5::File& file, const std::string& group) override;

  // The sums of state `period` (1 or 2), their config (P = 2) and what they hold.
  const PhaseAccumulator& accumulator(int period) const { return acc_[period - 1]; }
  const PhaseAveragerConfig& config() const { return cfg_; }
  int windows(int period) const { return windows_[period - 1]; }
  int pooledCycles(int period) const { return windows_[period - 1] * window_cycles_; }
  int firstWindowCycle() const { return start_cycle_; }
  // Windows swapped to the reference parity.
  int swappedWindows() const { return swapped_; }

 private:
  void endOfCycle();
  void closeWindow();
  PhaseAveragerConfig cfg_;
  int window_cycles_;
  PhaseAccumulator pending_, acc_[2];
  SteadyStateDetector detector_;
  std::vector<double> window_com_;  // centre-of-mass samples of the open window
  std::complex<double> reference_{0, 0};
  int windows_[2] = {0, 0};
  int start_cycle_ = -1;
  int swapped_ = 0;
  int current_cycle_ = -1;
  double cycle_com_ = 0;  // sum of com / M over the current cycle (steadyCycles' arithmetic)
};

}  // namespace granwave
