#pragma once
// The layer's energy budget phase by phase on the paper's scene (docs/studies.md, "Energy
// budget phase by phase"): the moving walls' work and the losses in pair collisions and at the
// walls over each phase interval of the window, particles (over seeds) beside the continuum
// (smooth and rough closures), and their totals per drive cycle.
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "studies/contract/Study.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

struct WaveFrontsConfig;

// One model's budget over its window: per phase interval (J, the paper's box), and per cycle.
struct BudgetSeries {
  std::string model;
  std::vector<double> phase;  // t/T at the end of each interval
  std::vector<double> work, pair_loss, wall_loss;
  // Per drive cycle (J): particles, mean and standard error over seeds; the continuum, exact.
  Measurement work_per_cycle, pair_per_cycle, wall_per_cycle;
  int seeds = 0;    // particles: seeds with a budget
  std::string why;  // why there is no budget ("" when there is)
  bool valid() const { return why.empty(); }
};

struct LawBudgets {
  BudgetSeries particles, smooth, rough;
};

LawBudgets analyseBudgets(const WaveFrontsConfig& config, const RunSet& runs, int law);
void writeBudgets(h5::File& file, const std::string& root, int law, const LawBudgets& budgets);

}  // namespace granwave
