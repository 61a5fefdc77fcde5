#pragma once
// How the dry-wet difference counts per frequency depend on the seeds: a bootstrap over seeds
// (Efron & Tibshirani 1993, ch. 13, percentile interval). Each resample draws, independently
// at every (f, Gamma) point (the runs of different points are independent simulations), as
// many seeds as were run there, with replacement, and the same draw for the dry and the wet
// layer of the point; the seeds vote again (SeedVote.hpp) and the differences are counted per
// frequency, in each symbol of the paper's diagram and in any of them (StabilityGrid.hpp).
// Reported: the median and the central 95 % interval of each count over the resamples. A
// point whose seeds all agree gives the same verdicts in every resample, so a grid of such
// points has intervals of zero width; a split point widens its frequency's interval. The
// draws are a fixed sequence (SeedResampling.hpp): the same on every build.
#include <string>
#include <vector>

#include "studies/stability/SeedBootstrap.hpp"
#include "studies/stability/StabilityGrid.hpp"
#include "studies/statistics/SeedResampling.hpp"

namespace granwave {

struct DifferenceCounts {
  Difference difference = Difference::any;
  std::vector<double> grid;                   // per frequency, the verdicts of all seeds
  std::vector<PercentileInterval> resampled;  // per frequency, over the resamples
};

inline constexpr int kDifferenceResamples = 1000;

// One entry per kDifferences. `grid`: the frequencies and Gamma values (its verdicts unused).
std::vector<DifferenceCounts> bootstrapDifferenceCounts(const StabilityGrid& grid,
                                                        const SeedPatterns& seeds,
                                                        int resamples = kDifferenceResamples);

}  // namespace granwave
