#include "coarse_grain/PhaseAverager.hpp"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>

#include "h5/H5Error.hpp"

namespace granwave {

PhaseAverager::PhaseAverager(const PhaseAveragerConfig& c)
    : cfg_(c),
      acc_(c.grid, c.samples_per_cycle * c.cycles_per_window, c.blocks),
      detector_(c.steady) {
  if (c.samples_per_cycle < 1 || c.cycles_per_window < 1 || c.blocks < 1)
    throw std::invalid_argument("phase averaging needs M >= 1, P >= 1 and at least one block");
  if (c.fixed_discard >= 0) {
    // Align the first pooled cycle with the window so the phase parity is the absolute one.
    const int P = c.cycles_per_window;
    start_cycle_ = (c.fixed_discard + P - 1) / P * P;
    const int usable = std::max(0, c.total_cycles - start_cycle_);
    cycles_per_block_ = std::max(P, usable / c.blocks / P * P);
  }
}

void PhaseAverager::endOfCycle(int cycle) {
  if (cycle_samples_ == 0) return;
  const bool steady = detector_.addCycle(cycle_height_sum_ / cycle_samples_);
  if (start_cycle_ < 0 && steady) {
    const int P = cfg_.cycles_per_window;
    start_cycle_ = (cycle + 1 + P - 1) / P * P;  // next window boundary
    const int usable = std::max(0, cfg_.total_cycles - start_cycle_);
    cycles_per_block_ = std::max(P, usable / cfg_.blocks / P * P);
  }
  cycle_height_sum_ = 0;
  cycle_samples_ = 0;
}

void PhaseAverager::observe(const Snapshot& s) {
  const int M = cfg_.samples_per_cycle;
  const int cycle = static_cast<int>(s.step / static_cast<std::uint64_t>(M));
  const int phase = static_cast<int>(s.step % static_cast<std::uint64_t>(M));
  if (cycle != current_cycle_) {
    if (current_cycle_ >= 0) endOfCycle(current_cycle_);
    current_cycle_ = cycle;
  }
  double zsum = 0;
  for (double z : s.z) zsum += z;
  cycle_height_sum_ += zsum / std::max(1, s.size());
  ++cycle_samples_;

  // The energy that crossed the layer's budget since the last record (Observables are
  // cumulative): pooled with this record's phase.
  const double now[PhaseAccumulator::kBudgetTerms] = {
      s.obs.wall_work, s.obs.dissipated_energy - s.obs.wall_dissipated_energy,
      s.obs.wall_dissipated_energy};
  double crossed[PhaseAccumulator::kBudgetTerms];
  for (int k = 0; k < PhaseAccumulator::kBudgetTerms; ++k) crossed[k] = now[k] - last_budget_[k];
  const bool has_interval = has_last_;
  std::copy(std::begin(now), std::end(now), std::begin(last_budget_));
  has_last_ = true;

  if (start_cycle_ < 0 || cycle < start_cycle_ || cycle >= cfg_.total_cycles) return;
  const int block = std::min(cfg_.blocks - 1, (cycle - start_cycle_) / cycles_per_block_);
  const int wphase = (cycle % cfg_.cycles_per_window) * M + phase;
  if (phase == 0) pooled_cycles_ = cycle - start_cycle_ + 1;
  acc_.countSnapshot(block, wphase, zsum, s.size());
  if (has_interval) acc_.addBudget(block, wphase, crossed);
  for (int k = 0; k < s.size(); ++k)
    acc_.add(block, wphase, s.x[k], s.z[k], s.vx[k], s.vz[k], s.omega[k]);
}

void PhaseAverager::saveState(h5::File& file, const std::string& group) const {
  acc_.save(file, group + "/sums");
  file.writeDataset(group + "/cycle_heights", detector_.history(), {detector_.history().size()});
  file.writeArrayAttribute<std::int64_t>(
      group, "counters",
      {start_cycle_, cycles_per_block_, pooled_cycles_, current_cycle_, cycle_samples_});
  file.writeAttribute(group, "cycle_height_sum", cycle_height_sum_);
  if (has_last_)
    file.writeArrayAttribute<double>(group, "last_budget",
                                     {last_budget_[0], last_budget_[1], last_budget_[2]});
}

void PhaseAverager::restoreState(const h5::File& file, const std::string& group) {
  acc_.restore(file, group + "/sums");
  detector_ = SteadyStateDetector(cfg_.steady);
  for (double h : file.readDataset<double>(group + "/cycle_heights")) detector_.addCycle(h);
  const auto c = file.readArrayAttribute<std::int64_t>(group, "counters");
  if (c.size() != 5)
    throw h5::H5Error(file.name() + ": " + group + " counters hold " + std::to_string(c.size()) +
                      " values, expected 5");
  start_cycle_ = static_cast<int>(c[0]);
  cycles_per_block_ = static_cast<int>(c[1]);
  pooled_cycles_ = static_cast<int>(c[2]);
  current_cycle_ = static_cast<int>(c[3]);
  cycle_samples_ = static_cast<int>(c[4]);
  cycle_height_sum_ = file.readAttribute<double>(group, "cycle_height_sum");
  has_last_ = file.hasAttribute(group, "last_budget");
  if (has_last_) {
    const auto last = file.readArrayAttribute<double>(group, "last_budget");
    if (last.size() != PhaseAccumulator::kBudgetTerms)
      throw h5::H5Error(file.name() + ": " + group + " last_budget holds " +
                        std::to_string(last.size()) + " values, expected 3");
    std::copy(last.begin(), last.end(), std::begin(last_budget_));
  }
}

}  // namespace granwave
