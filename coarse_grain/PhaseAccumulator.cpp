#include "coarse_grain/PhaseAccumulator.hpp"

#include <limits>

namespace granwave {

PhaseAccumulator::PhaseAccumulator(const FieldGrid& grid, int phases, int blocks)
    : grid_(grid),
      phases_(phases),
      blocks_(blocks),
      sums_(static_cast<std::size_t>(blocks) * phases * grid.cells()),
      snapshots_(static_cast<std::size_t>(blocks) * phases, 0.0),
      z_sum_(snapshots_.size(), 0.0),
      particles_(snapshots_.size(), 0.0) {}

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

}  // namespace granwave
