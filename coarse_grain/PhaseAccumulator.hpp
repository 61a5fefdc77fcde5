#pragma once
// Pooled sums per (block, phase, cell): the raw material of phase-averaged fields. Sums of
// v, v^2, omega, omega^2 and counts are kept so that any block, or all of them, can be turned
// into means and variances afterwards (MercuryCG keeps fields that know their arithmetic in
// the same way). Independent blocks of cycles give honest uncertainties.
#include <cstddef>
#include <string>
#include <vector>

#include "coarse_grain/FieldGrid.hpp"
#include "h5/File.hpp"

namespace granwave {

struct CellSums {
  double n = 0, vx = 0, vz = 0, vv = 0, vx2 = 0, w = 0, w2 = 0;
  void add(double ux, double uz, double om) {
    n += 1;
    vx += ux;
    vz += uz;
    vv += ux * ux + uz * uz;
    vx2 += ux * ux;
    w += om;
    w2 += om * om;
  }
  void merge(const CellSums& o) {
    n += o.n;
    vx += o.vx;
    vz += o.vz;
    vv += o.vv;
    vx2 += o.vx2;
    w += o.w;
    w2 += o.w2;
  }
};

class PhaseAccumulator {
 public:
  PhaseAccumulator() = default;
  PhaseAccumulator(const FieldGrid& grid, int phases, int blocks);

  const FieldGrid& grid() const { return grid_; }
  int phases() const { return phases_; }
  int blocks() const { return blocks_; }

  // One particle seen at `phase` in `block`; outside the grid it is ignored.
  void add(int block, int phase, double x, double z, double vx, double vz, double omega);
  // One snapshot pooled at (block, phase): counted for the snapshot-normalised density.
  // One snapshot pooled at (block, phase), with its particles' summed height (for the
  // centre of mass) and their number.
  void countSnapshot(int block, int phase, double z_sum, double particles) {
    ++snapshots_[block * phases_ + phase];
    z_sum_[block * phases_ + phase] += z_sum;
    particles_[block * phases_ + phase] += particles;
  }

  // The layer's energy budget over the recorded interval that ends at (block, phase): the
  // work of the moving walls, the energy lost in pair collisions and at the walls (J; the
  // increments of the engine's cumulative Observables), summed over the pooled snapshots.
  static constexpr int kBudgetTerms = 3;
  // A non-finite term (a run file without one of the observables) leaves no budget at all.
  void addBudget(int block, int phase, const double (&crossed)[kBudgetTerms]);
  // Whether any budget was added (an accumulator fed without one, or restored from a
  // checkpoint that had none, has no budget to give).
  bool hasBudget() const { return has_budget_ && !budget_lost_; }
  // The sum of `term` at (block, phase), and the number of records that carried a budget
  // there (a record with no record before it carries none); block = -1 pools all blocks.
  double budget(int block, int phase, int term) const;
  double budgetRecords(int block, int phase) const { return budget(block, phase, kBudgetTerms); }

  const CellSums& at(int block, int phase, int cell) const {
    return sums_[(static_cast<std::size_t>(block) * phases_ + phase) * grid_.cells() + cell];
  }
  double snapshots(int block, int phase) const { return snapshots_[block * phases_ + phase]; }
  // Mean particle height at (block, phase); block = -1 pools all blocks.
  double centerOfMass(int block, int phase) const;
  // All blocks merged (block = -1 in the accessors of PhaseFields).
  CellSums pooled(int phase, int cell) const;
  double pooledSnapshots(int phase) const;

  // Adds block `from_block` of `from` (same grid and phases) to block `to_block`, phase k of
  // `from` landing on phase (k + shift) mod phases (a period-2 episode of the other parity).
  void mergeBlock(const PhaseAccumulator& from, int from_block, int to_block, int shift);
  void clear();  // every sum back to zero

  // Checkpoints: the sums as stored; restore() requires the same grid, phases and blocks.
  void save(h5::File& file, const std::string& group) const;
  void restore(const h5::File& file, const std::string& group);

 private:
  FieldGrid grid_;
  int phases_ = 0, blocks_ = 0;
  std::vector<CellSums> sums_;
  std::vector<double> snapshots_, z_sum_, particles_;
  std::vector<double> budget_;  // [block][phase][term], then the records counted
  bool has_budget_ = false;
  // Restored from sums without a budget, or fed a non-finite one: none can be completed.
  bool budget_lost_ = false;
};

}  // namespace granwave
