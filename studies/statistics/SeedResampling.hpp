#pragma once
// A bootstrap over seeds (Efron & Tibshirani, "An Introduction to the Bootstrap", 1993,
// chs. 6 and 13): each resample draws as many seeds as were run, with replacement, and the
// statistic is computed again from the drawn seeds; its spread over the resamples is the
// uncertainty that the choice of seeds leaves. The draws come from a fixed 64-bit Mersenne
// Twister sequence (index = draw mod seeds), so a study's bootstrap is the same on every build.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace granwave {

// `resamples` draws of `seeds` indices into the seeds, each drawn with replacement.
std::vector<std::vector<std::size_t>> seedDraws(std::size_t seeds, int resamples,
                                                std::uint64_t rng_seed);

// The seeds a study adds to `seeds` when a verdict stays undecided, up to `max_seeds` in all:
// the next integers after the largest (none if there are already max_seeds).
std::vector<int> seedsAfter(const std::vector<int>& seeds, int max_seeds);

// The median and the central 95 % interval (2.5 % and 97.5 % quantiles, linear interpolation
// between order statistics) of a statistic over the resamples; NaN if there is none.
struct PercentileInterval {
  double median = 0, low = 0, high = 0;
  int resamples = 0;
};
PercentileInterval percentileInterval(std::vector<double> values);

}  // namespace granwave
