#include "coarse_grain/SteadyStateDetector.hpp"

#include <cmath>

namespace granwave {

namespace {
struct Stats {
  double mean = 0, var = 0;
};
Stats stats(const std::vector<double>& h, int from, int n) {
  Stats s;
  for (int k = 0; k < n; ++k) s.mean += h[from + k] / n;
  for (int k = 0; k < n; ++k) s.var += (h[from + k] - s.mean) * (h[from + k] - s.mean) / (n - 1);
  return s;
}
}  // namespace

bool SteadyStateDetector::addCycle(double mean_height) {
  h_.push_back(mean_height);
  if (steady()) return true;
  const int w = opt_.window;
  const int n = cycles();
  // Candidate start c = n - 2w: windows [c, c + w) and [c + w, n).
  const int c = n - 2 * w;
  if (c < opt_.min_cycles) return false;
  const Stats a = stats(h_, c, w), b = stats(h_, c + w, w);
  const double se = std::sqrt((a.var + b.var) / w);
  const double tol = std::max(opt_.sigmas * se, opt_.floor * std::abs(b.mean));
  if (std::abs(a.mean - b.mean) <= tol) steady_from_ = c;
  return steady();
}

int steadyCycles(const std::vector<double>& com, int M, const SteadyStateOptions& o) {
  SteadyStateDetector det(o);
  const int cycles = static_cast<int>(com.size()) / M;
  for (int k = 0; k < cycles; ++k) {
    double mean = 0;
    for (int j = 0; j < M; ++j) mean += com[static_cast<std::size_t>(k) * M + j] / M;
    if (det.addCycle(mean)) return det.steadyFrom();
  }
  return -1;
}

}  // namespace granwave
