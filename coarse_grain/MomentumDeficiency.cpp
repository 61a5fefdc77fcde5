#include "coarse_grain/MomentumDeficiency.hpp"

#include <cmath>
#include <stdexcept>

namespace granwave {

namespace {

// r_x from the dry and wet RMS(v_x) at (phase, row), NaN where a layer has none.
template <class Dry, class Wet>
Deficiency deficiencyOf(int phases, int nz, Dry dry_rms, Wet wet_rms,
                        const std::vector<bool>& select, double min_rms) {
  Deficiency r;
  r.phases = phases;
  r.nz = nz;
  r.ratio.assign(static_cast<std::size_t>(r.phases) * r.nz, kNaN);
  r.row_mean.assign(r.phases, kNaN);
  double sum = 0, sum2 = 0;
  for (int ph = 0; ph < r.phases; ++ph) {
    double rs = 0;
    int rn = 0;
    for (int j = 0; j < r.nz; ++j) {
      const double a = dry_rms(ph, j);
      const double b = wet_rms(ph, j);
      if (!std::isfinite(a) || !std::isfinite(b) || b < min_rms) continue;
      r.ratio[static_cast<std::size_t>(ph) * r.nz + j] = a / b;
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

void requireSameShape(const PhaseFields& dry, const PhaseFields& wet) {
  if (dry.phases != wet.phases || dry.nz != wet.nz)
    throw std::invalid_argument("deficiency: dry and wet fields have different phases or rows");
}

}  // namespace

Deficiency momentumDeficiency(const PhaseFields& dry, const PhaseFields& wet,
                              const std::vector<bool>& select, double min_rms) {
  requireSameShape(dry, wet);
  return deficiencyOf(
      dry.phases, dry.nz, [&](int ph, int j) { return dry.profile_rms_velocity_x[dry.row(ph, j)]; },
      [&](int ph, int j) { return wet.profile_rms_velocity_x[wet.row(ph, j)]; }, select, min_rms);
}

Deficiency momentumDeficiency(const PhaseFields& dry, const PhaseFields& wet,
                              const DeficiencyOptions& o, const PhaseFields* dry_block,
                              const PhaseFields* wet_block) {
  requireSameShape(dry, wet);
  const PhaseFields& d = dry_block ? *dry_block : dry;
  const PhaseFields& w = wet_block ? *wet_block : wet;
  const int n = wet.phases;
  auto shifted = [&](int ph) { return ((ph + o.dry_shift) % n + n) % n; };
  auto dense = [&](int ph, int j) {
    return dry.profile_area_fraction[dry.row(shifted(ph), j)] >= o.min_area_fraction &&
           wet.profile_area_fraction[wet.row(ph, j)] >= o.min_area_fraction;
  };
  return deficiencyOf(
      n, wet.nz,
      [&](int ph, int j) {
        return dense(ph, j) ? d.profile_rms_velocity_x[d.row(shifted(ph), j)] : kNaN;
      },
      [&](int ph, int j) { return w.profile_rms_velocity_x[w.row(ph, j)]; }, o.select, o.min_rms);
}

}  // namespace granwave
