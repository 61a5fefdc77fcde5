#include "studies/statistics/SeedResampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace granwave {

std::vector<std::vector<std::size_t>> seedDraws(std::size_t seeds, int resamples,
                                                std::uint64_t rng_seed) {
  std::vector<std::vector<std::size_t>> draws;
  if (seeds == 0) return draws;
  std::mt19937_64 rng(rng_seed);
  for (int r = 0; r < resamples; ++r) {
    std::vector<std::size_t> draw(seeds);
    for (std::size_t& k : draw) k = static_cast<std::size_t>(rng() % seeds);
    draws.push_back(std::move(draw));
  }
  return draws;
}

namespace {
// Quantile q of sorted values, linear between order statistics (Hyndman & Fan type 7).
double quantile(const std::vector<double>& sorted, double q) {
  const double x = q * static_cast<double>(sorted.size() - 1);
  const std::size_t i = static_cast<std::size_t>(std::floor(x));
  if (i + 1 >= sorted.size()) return sorted.back();
  return sorted[i] + (x - static_cast<double>(i)) * (sorted[i + 1] - sorted[i]);
}
}  // namespace

PercentileInterval percentileInterval(std::vector<double> values) {
  std::erase_if(values, [](double v) { return !std::isfinite(v); });
  PercentileInterval p;
  p.resamples = static_cast<int>(values.size());
  if (values.empty()) {
    p.median = p.low = p.high = std::numeric_limits<double>::quiet_NaN();
    return p;
  }
  std::sort(values.begin(), values.end());
  p.median = quantile(values, 0.5);
  p.low = quantile(values, 0.025);
  p.high = quantile(values, 0.975);
  return p;
}

std::vector<int> seedsAfter(const std::vector<int>& seeds, int max_seeds) {
  std::vector<int> out;
  int next = seeds.empty() ? 1 : *std::max_element(seeds.begin(), seeds.end()) + 1;
  for (std::size_t k = seeds.size(); k < static_cast<std::size_t>(max_seeds); ++k)
    out.push_back(next++);
  return out;
}

}  // namespace granwave
