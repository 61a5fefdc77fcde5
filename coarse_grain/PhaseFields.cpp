#include "coarse_grain/PhaseFields.hpp"

#include <cmath>
#include <numbers>

namespace granwave {

PhaseFields computeFields(const PhaseAccumulator& acc, const FieldParams& p, int block) {
  const FieldGrid& g = acc.grid();
  PhaseFields f;
  f.phases = acc.phases();
  f.nz = g.nz;
  f.nx = g.nx;
  const std::size_t ncell = static_cast<std::size_t>(f.phases) * g.nz * g.nx;
  const std::size_t nrow = static_cast<std::size_t>(f.phases) * g.nz;
  for (auto* v : {&f.count, &f.area_fraction, &f.velocity_x, &f.velocity_z, &f.temperature,
                  &f.rotational_temperature})
    v->assign(ncell, kNaN);
  for (auto* v : {&f.profile_temperature, &f.profile_velocity_z, &f.profile_rms_velocity_x,
                  &f.profile_area_fraction})
    v->assign(nrow, kNaN);
  f.center_of_mass_height.assign(f.phases, kNaN);
  f.snapshots.assign(f.phases, 0.0);
  const double disk = std::numbers::pi * p.diameter * p.diameter / 4.0;

  for (int ph = 0; ph < f.phases; ++ph) {
    const double snaps = block < 0 ? acc.pooledSnapshots(ph) : acc.snapshots(block, ph);
    f.snapshots[ph] = snaps;
    if (snaps <= 0) continue;
    for (int j = 0; j < g.nz; ++j) {
      double t_sum = 0, vz_sum = 0, vx_sum = 0, vx2_sum = 0, nu_sum = 0;
      int valid = 0;
      for (int i = 0; i < g.nx; ++i) {
        const int c = j * g.nx + i;
        const CellSums s = block < 0 ? acc.pooled(ph, c) : acc.at(block, ph, c);
        const std::size_t k = f.cell(ph, j, i);
        f.count[k] = s.n;
        f.area_fraction[k] = s.n / snaps * disk / (g.wx * g.wz);
        nu_sum += f.area_fraction[k];
        if (s.n < p.min_count) continue;
        const double mx = s.vx / s.n, mz = s.vz / s.n, mw = s.w / s.n;
        f.velocity_x[k] = mx;
        f.velocity_z[k] = mz;
        // sum (v - v~)^2 = sum v^2 - n |v~|^2
        f.temperature[k] = p.mass * std::max(0.0, s.vv - s.n * (mx * mx + mz * mz)) / (2 * s.n);
        f.rotational_temperature[k] = p.inertia * std::max(0.0, s.w2 - s.n * mw * mw) / (2 * s.n);
        t_sum += f.temperature[k];
        vz_sum += mz;
        vx_sum += mx;
        vx2_sum += mx * mx;
        ++valid;
      }
      const std::size_t r = f.row(ph, j);
      f.profile_area_fraction[r] = nu_sum / g.nx;
      if (valid > 0) {
        f.profile_temperature[r] = t_sum / valid;
        f.profile_velocity_z[r] = vz_sum / valid;
        const double mean_vx = vx_sum / valid;
        f.profile_rms_velocity_x[r] = std::sqrt(std::max(0.0, vx2_sum / valid - mean_vx * mean_vx));
      }
    }
    f.center_of_mass_height[ph] = acc.centerOfMass(block, ph);
  }
  if (acc.hasBudget()) {
    std::vector<double>* terms[PhaseAccumulator::kBudgetTerms] = {&f.plate_work, &f.pair_loss,
                                                                  &f.wall_loss};
    for (int t = 0; t < PhaseAccumulator::kBudgetTerms; ++t) {
      terms[t]->assign(f.phases, kNaN);
      for (int ph = 0; ph < f.phases; ++ph)
        if (const double n = acc.budgetRecords(block, ph); n > 0)
          (*terms[t])[ph] = acc.budget(block, ph, t) / n;
    }
  }
  return f;
}

}  // namespace granwave
