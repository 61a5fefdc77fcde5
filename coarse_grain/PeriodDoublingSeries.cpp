#include "coarse_grain/PeriodDoublingSeries.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "coarse_grain/PeriodDetector.hpp"

namespace granwave {

namespace {

// tau = 1 + 2 sum_k rho_k over the initial positive autocorrelations; 0 if the series is
// constant (no estimate).
double integratedAutocorrelation(const std::vector<int>& s) {
  const std::size_t n = s.size();
  double mean = 0;
  for (int v : s) mean += static_cast<double>(v) / static_cast<double>(n);
  double c0 = 0;
  for (int v : s) c0 += (v - mean) * (v - mean);
  if (c0 <= 0) return 0;
  double tau = 1;
  for (std::size_t k = 1; k < n; ++k) {
    double ck = 0;
    for (std::size_t i = 0; i + k < n; ++i) ck += (s[i] - mean) * (s[i + k] - mean);
    const double rho = ck / c0;
    if (rho <= 0) break;
    tau += 2 * rho;
  }
  return tau;
}

}  // namespace

void wilsonInterval(double p, double n, double& low, double& high) {
  constexpr double z = 1.959963984540054;  // two-sided 95 %
  const double z2n = z * z / n;
  const double centre = (p + 0.5 * z2n) / (1 + z2n);
  const double half = z * std::sqrt(p * (1 - p) / n + 0.25 * z2n / n) / (1 + z2n);
  low = std::max(0.0, centre - half);
  high = std::min(1.0, centre + half);
}

PeriodDoublingSeries periodDoublingSeries(const std::vector<double>& com, int M, int discard,
                                          int window, double threshold) {
  if (window <= 0 || window % 12 != 0)
    throw std::invalid_argument("period-doubling series: window of " + std::to_string(window) +
                                " cycles; a positive multiple of 12 is needed");
  const int total = M > 0 ? static_cast<int>(com.size()) / M : 0;
  const int windows = (total - discard) / window;
  if (M < 4 || windows < 1)
    throw std::invalid_argument("period-doubling series needs at least one window of " +
                                std::to_string(window) + " steady cycles, got " +
                                std::to_string(std::max(0, total - discard)));
  PeriodDoublingSeries r;
  r.window_cycles = window;
  r.first_cycle = total - windows * window;
  const std::size_t per = static_cast<std::size_t>(window) * static_cast<std::size_t>(M);
  for (int w = 0; w < windows; ++w) {
    const auto begin = com.begin() + static_cast<long>((r.first_cycle + w * window) * M);
    const std::vector<double> slice(begin, begin + static_cast<long>(per));
    const double strength = detectPeriod(slice, 0, {M}).strength[2];
    r.f2_strength.push_back(strength);
    r.period2.push_back(strength > threshold ? 1 : 0);
    r.period2_share += static_cast<double>(r.period2.back()) / windows;
    if (w > 0) r.switches += r.period2[w] != r.period2[w - 1];
  }
  const double tau = integratedAutocorrelation(r.period2);
  r.effective_windows = tau > 0 ? std::min<double>(windows, windows / tau) : 1.0;
  wilsonInterval(r.period2_share, r.effective_windows, r.share_low, r.share_high);
  return r;
}

}  // namespace granwave
