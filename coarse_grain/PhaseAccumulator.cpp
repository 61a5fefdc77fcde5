#include "coarse_grain/PhaseAccumulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "h5/H5Error.hpp"

namespace granwave {

PhaseAccumulator::PhaseAccumulator(const FieldGrid& grid, int phases, int blocks)
    : grid_(grid),
      phases_(phases),
      blocks_(blocks),
      sums_(static_cast<std::size_t>(blocks) * phases * grid.cells()),
      snapshots_(static_cast<std::size_t>(blocks) * phases, 0.0),
      z_sum_(snapshots_.size(), 0.0),
      particles_(snapshots_.size(), 0.0),
      budget_(snapshots_.size() * (kBudgetTerms + 1), 0.0) {}

void PhaseAccumulator::addBudget(int block, int phase, const double (&crossed)[kBudgetTerms]) {
  if (budget_lost_) return;
  for (double x : crossed)
    if (!std::isfinite(x)) {
      budget_lost_ = true;
      return;
    }
  const std::size_t at = (static_cast<std::size_t>(block) * phases_ + phase) * (kBudgetTerms + 1);
  for (int k = 0; k < kBudgetTerms; ++k) budget_[at + k] += crossed[k];
  budget_[at + kBudgetTerms] += 1;
  has_budget_ = true;
}

double PhaseAccumulator::budget(int block, int phase, int term) const {
  double sum = 0;
  for (int b = 0; b < blocks_; ++b)
    if (block < 0 || b == block)
      sum += budget_[(static_cast<std::size_t>(b) * phases_ + phase) * (kBudgetTerms + 1) + term];
  return sum;
}

double PhaseAccumulator::centerOfMass(int block, int phase) const {
  double z = 0, n = 0;
  for (int b = 0; b < blocks_; ++b) {
    if (block >= 0 && b != block) continue;
    z += z_sum_[b * phases_ + phase];
    n += particles_[b * phases_ + phase];
  }
  return n > 0 ? z / n : std::numeric_limits<double>::quiet_NaN();
}

void PhaseAccumulator::add(int block, int phase, double x, double z, double vx, double vz,
                           double omega) {
  const int cell = grid_.cellOf(x, z);
  if (cell < 0) return;
  sums_[(static_cast<std::size_t>(block) * phases_ + phase) * grid_.cells() + cell].add(vx, vz,
                                                                                        omega);
}

void PhaseAccumulator::mergeBlock(const PhaseAccumulator& from, int from_block, int to_block,
                                  int shift) {
  const int cells = grid_.cells();
  for (int k = 0; k < phases_; ++k) {
    const int to = (k + shift) % phases_;
    const std::size_t i = static_cast<std::size_t>(from_block) * phases_ + k;
    const std::size_t j = static_cast<std::size_t>(to_block) * phases_ + to;
    snapshots_[j] += from.snapshots_[i];
    z_sum_[j] += from.z_sum_[i];
    particles_[j] += from.particles_[i];
    for (int t = 0; t <= kBudgetTerms; ++t)
      budget_[j * (kBudgetTerms + 1) + t] += from.budget_[i * (kBudgetTerms + 1) + t];
    for (int c = 0; c < cells; ++c) sums_[j * cells + c].merge(from.sums_[i * cells + c]);
  }
  has_budget_ = has_budget_ || from.has_budget_;
  budget_lost_ = budget_lost_ || from.budget_lost_;
}

void PhaseAccumulator::clear() {
  std::fill(sums_.begin(), sums_.end(), CellSums{});
  std::fill(snapshots_.begin(), snapshots_.end(), 0.0);
  std::fill(z_sum_.begin(), z_sum_.end(), 0.0);
  std::fill(particles_.begin(), particles_.end(), 0.0);
  std::fill(budget_.begin(), budget_.end(), 0.0);
  has_budget_ = budget_lost_ = false;
}

CellSums PhaseAccumulator::pooled(int phase, int cell) const {
  CellSums s;
  for (int b = 0; b < blocks_; ++b) s.merge(at(b, phase, cell));
  return s;
}

double PhaseAccumulator::pooledSnapshots(int phase) const {
  double s = 0;
  for (int b = 0; b < blocks_; ++b) s += snapshots(b, phase);
  return s;
}

// Only the visited cells are stored (most of a container is empty at most phases: the
// paper's scene keeps 5 % of them), as their indices and sums.
void PhaseAccumulator::save(h5::File& file, const std::string& group) const {
  file.createGroup(group);
  std::vector<double> sums;
  std::vector<std::uint64_t> visited;
  for (std::size_t k = 0; k < sums_.size(); ++k) {
    const CellSums& c = sums_[k];
    if (c.n == 0) continue;
    visited.push_back(k);
    sums.insert(sums.end(), {c.n, c.vx, c.vz, c.vv, c.vx2, c.w, c.w2});
  }
  file.writeAttribute<std::uint64_t>(group, "cells", sums_.size());
  file.writeDataset(group + "/visited", visited, {visited.size()});
  file.writeDataset(group + "/cell_sums", sums, {visited.size(), 7});
  file.writeDataset(group + "/snapshots", snapshots_, {snapshots_.size()});
  file.writeDataset(group + "/z_sum", z_sum_, {z_sum_.size()});
  file.writeDataset(group + "/particles", particles_, {particles_.size()});
  if (budget_lost_) return;  // restored without one: none is written, none can be resumed
  file.writeDataset(group + "/budget", budget_, {budget_.size()});
  file.writeAttribute<std::uint64_t>(group + "/budget", "added", has_budget_ ? 1 : 0);
}

void PhaseAccumulator::restore(const h5::File& file, const std::string& group) {
  // The shapes are checked: a checkpoint of another grid is refused by name.
  if (file.readAttribute<std::uint64_t>(group, "cells") != sums_.size())
    throw h5::H5Error(file.name() + ": " + group + " holds sums of another field grid");
  const auto visited = file.readDataset<std::uint64_t>(group + "/visited");
  const auto sums = file.readDataset<double>(group + "/cell_sums", {visited.size(), 7});
  snapshots_ = file.readDataset<double>(group + "/snapshots", {snapshots_.size()});
  z_sum_ = file.readDataset<double>(group + "/z_sum", {z_sum_.size()});
  particles_ = file.readDataset<double>(group + "/particles", {particles_.size()});
  // A checkpoint without a budget leaves none: its pooled cycles' share is unknown.
  budget_lost_ = !file.exists(group + "/budget");
  has_budget_ = !budget_lost_ && file.readAttribute<std::uint64_t>(group + "/budget", "added") != 0;
  budget_ = budget_lost_ ? std::vector<double>(budget_.size(), 0.0)
                         : file.readDataset<double>(group + "/budget", {budget_.size()});
  std::fill(sums_.begin(), sums_.end(), CellSums{});
  for (std::size_t v = 0; v < visited.size(); ++v) {
    if (visited[v] >= sums_.size())
      throw h5::H5Error(file.name() + ": " + group + "/visited names cell " +
                        std::to_string(visited[v]) + " of " + std::to_string(sums_.size()));
    const double* c = &sums[7 * v];
    sums_[visited[v]] = {c[0], c[1], c[2], c[3], c[4], c[5], c[6]};
  }
}

}  // namespace granwave
