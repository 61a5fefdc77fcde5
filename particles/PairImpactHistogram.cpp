#include "particles/PairImpactHistogram.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace granwave {

PairImpactHistogram::PairImpactHistogram(const PairImpactBins& bins) : bins_(bins) {
  if (!(bins.speed_max > 0) || bins.speed_bins < 1 || bins.phase_bins < 1 || !(bins.period >= 0))
    throw std::invalid_argument(
        "pair impact histogram: speed_max > 0, speed_bins >= 1, phase_bins >= 1 and period >= 0 "
        "expected");
  counts_.assign(static_cast<std::size_t>(bins.phase_bins) * bins.speed_bins, 0);
}

void PairImpactHistogram::pairImpact(const PairImpact& im) {
  if (im.time < bins_.start_time || im.height < bins_.z_min || im.height > bins_.z_max) return;
  int phase = 0;
  if (bins_.period > 0) {
    const double x = im.time / bins_.period;
    phase = static_cast<int>((x - std::floor(x)) * bins_.phase_bins);
    if (phase >= bins_.phase_bins) phase = bins_.phase_bins - 1;  // round-off at x -> 1
  }
  int k = static_cast<int>(im.normal_speed / bins_.speed_max * bins_.speed_bins);
  if (k >= bins_.speed_bins) k = bins_.speed_bins - 1;
  if (k < 0) k = 0;
  ++counts_[static_cast<std::size_t>(phase) * bins_.speed_bins + k];
  ++total_;
}

double PairImpactHistogram::weightedMean(const std::function<double(double)>& f,
                                         const std::vector<bool>& use) const {
  double sum = 0, n = 0;
  for (int p = 0; p < bins_.phase_bins; ++p) {
    if (!use.empty() && !use[p]) continue;
    for (int k = 0; k < bins_.speed_bins; ++k) {
      const double c = static_cast<double>(count(p, k));
      if (c == 0) continue;
      sum += c * f(speedBinCentre(k));
      n += c;
    }
  }
  return n > 0 ? sum / n : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace granwave
