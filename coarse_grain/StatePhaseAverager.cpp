#include "coarse_grain/StatePhaseAverager.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "coarse_grain/PeriodDoublingSeries.hpp"
#include "h5/H5Error.hpp"

namespace granwave {

namespace {
PhaseAveragerConfig twoCycleWindows(PhaseAveragerConfig c) {
  c.cycles_per_window = 2;
  return c;
}
}  // namespace

StatePhaseAverager::StatePhaseAverager(const PhaseAveragerConfig& c, int window_cycles)
    : cfg_(twoCycleWindows(c)),
      window_cycles_(window_cycles),
      pending_(c.grid, 2 * c.samples_per_cycle, 1),
      acc_{PhaseAccumulator(c.grid, 2 * c.samples_per_cycle, c.blocks),
           PhaseAccumulator(c.grid, 2 * c.samples_per_cycle, c.blocks)},
      detector_(c.steady) {
  if (c.samples_per_cycle < 4 || c.blocks < 1 || window_cycles <= 0 || window_cycles % 12 != 0)
    throw std::invalid_argument(
        "state-conditioned averaging needs M >= 4, at least one block and windows of a "
        "positive multiple of 12 cycles");
}

// The series' first window (PeriodDoublingSeries over runPeriod's transient), or the next
// window of the same grid that is still to come.
void StatePhaseAverager::endOfCycle() {
  if (start_cycle_ >= 0 || !detector_.addCycle(cycle_com_)) return;
  int first = std::max({3, cfg_.total_cycles / 5, detector_.steadyFrom()});
  first += first % 2;
  if (first <= current_cycle_)
    first += (current_cycle_ + 1 - first + window_cycles_ - 1) / window_cycles_ * window_cycles_;
  start_cycle_ = first;
}

void StatePhaseAverager::observe(const Snapshot& s) {
  const int M = cfg_.samples_per_cycle;
  const int cycle = static_cast<int>(s.step / static_cast<std::uint64_t>(M));
  const int phase = static_cast<int>(s.step % static_cast<std::uint64_t>(M));
  if (cycle != current_cycle_) {
    if (current_cycle_ >= 0) endOfCycle();
    current_cycle_ = cycle;
    cycle_com_ = 0;
  }
  cycle_com_ += s.obs.center_of_mass_height / M;
  if (start_cycle_ < 0 || cycle < start_cycle_) return;
  const int whole = (cfg_.total_cycles - start_cycle_) / window_cycles_ * window_cycles_;
  if (cycle >= start_cycle_ + whole) return;
  double zsum = 0;
  for (double z : s.z) zsum += z;
  const int wphase = (cycle % 2) * M + phase;
  pending_.countSnapshot(0, wphase, zsum, s.size());
  for (int k = 0; k < s.size(); ++k)
    pending_.add(0, wphase, s.x[k], s.z[k], s.vx[k], s.vz[k], s.omega[k]);
  window_com_.push_back(s.obs.center_of_mass_height);
  if (phase == M - 1 && (cycle - start_cycle_ + 1) % window_cycles_ == 0) closeWindow();
}

void StatePhaseAverager::closeWindow() {
  const int M = cfg_.samples_per_cycle;
  // A window with a missing record (not expected from the engine) is left out whole.
  if (window_com_.size() == static_cast<std::size_t>(window_cycles_) * M) {
    const F2Window w = f2Window(window_com_.data(), window_cycles_, M);
    const int state = w.period2 ? 2 : 1;
    int shift = 0;
    if (state == 2 && reference_ == std::complex<double>(0, 0)) {
      reference_ = w.f2;
    } else if (state == 2 && std::real(w.f2 * std::conj(reference_)) < 0) {
      shift = M;
      ++swapped_;
    }
    acc_[state - 1].mergeBlock(pending_, 0, windows_[state - 1] % cfg_.blocks, shift);
    ++windows_[state - 1];
  }
  pending_.clear();
  window_com_.clear();
}

void StatePhaseAverager::saveState(h5::File& file, const std::string& group) const {
  pending_.save(file, group + "/pending");
  acc_[0].save(file, group + "/period1");
  acc_[1].save(file, group + "/period2");
  file.writeDataset(group + "/cycle_heights", detector_.history(), {detector_.history().size()});
  file.writeDataset(group + "/window_com", window_com_, {window_com_.size()});
  file.writeArrayAttribute<std::int64_t>(
      group, "counters", {windows_[0], windows_[1], start_cycle_, swapped_, current_cycle_});
  file.writeArrayAttribute<double>(group, "sums",
                                   {cycle_com_, std::real(reference_), std::imag(reference_)});
}

void StatePhaseAverager::restoreState(const h5::File& file, const std::string& group) {
  pending_.restore(file, group + "/pending");
  acc_[0].restore(file, group + "/period1");
  acc_[1].restore(file, group + "/period2");
  detector_ = SteadyStateDetector(cfg_.steady);
  for (double h : file.readDataset<double>(group + "/cycle_heights")) detector_.addCycle(h);
  window_com_ = file.readDataset<double>(group + "/window_com");
  const auto c = file.readArrayAttribute<std::int64_t>(group, "counters");
  const auto d = file.readArrayAttribute<double>(group, "sums");
  if (c.size() != 5 || d.size() != 3)
    throw h5::H5Error(file.name() + ": " + group +
                      " counters hold the wrong number of values (expected 5 and 3)");
  windows_[0] = static_cast<int>(c[0]);
  windows_[1] = static_cast<int>(c[1]);
  start_cycle_ = static_cast<int>(c[2]);
  swapped_ = static_cast<int>(c[3]);
  current_cycle_ = static_cast<int>(c[4]);
  cycle_com_ = d[0];
  reference_ = {d[1], d[2]};
}

}  // namespace granwave
