#include "coarse_grain/MomentumDeficiency.hpp"

#include <cmath>
#include <stdexcept>

namespace granwave {

Deficiency momentumDeficiency(const PhaseFields& dry, const PhaseFields& wet,
                              const std::vector<bool>& select, double min_rms) {
  if (dry.phases != wet.phases || dry.nz != wet.nz)
    throw std::invalid_argument("deficiency: dry and wet fields have different phases or rows");
  Deficiency r;
  r.phases = dry.phases;
  r.nz = dry.nz;
  r.ratio.assign(static_cast<std::size_t>(r.phases) * r.nz, kNaN);
  r.row_mean.assign(r.phases, kNaN);
  double sum = 0, sum2 = 0;
  for (int ph = 0; ph < r.phases; ++ph) {
    double rs = 0;
    int rn = 0;
    for (int j = 0; j < r.nz; ++j) {
      const double a = dry.profile_rms_velocity_x[dry.row(ph, j)];
      const double b = wet.profile_rms_velocity_x[wet.row(ph, j)];
      if (!std::isfinite(a) || !std::isfinite(b) || b < min_rms) continue;
      r.ratio[dry.row(ph, j)] = a / b;
      rs += a / b;
      ++rn;
    }
    if (rn == 0) continue;
    r.row_mean[ph] = rs / rn;
    if (!select.empty() && !select[ph]) continue;
    sum += r.row_mean[ph];
    sum2 += r.row_mean[ph] * r.row_mean[ph];
    ++r.phases_used;
  }
  if (r.phases_used > 0) {
    r.mean = sum / r.phases_used;
    if (r.phases_used > 1)
      r.std_dev =
          std::sqrt(std::max(0.0, (sum2 - r.phases_used * r.mean * r.mean) / (r.phases_used - 1)));
  }
  return r;
}

}  // namespace granwave
