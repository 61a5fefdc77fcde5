#include "studies/sound_speed/FrontStates.hpp"

#include <cmath>

namespace granwave {

std::vector<int> episodePhases(const PhaseProfiles& p, int first) {
  std::vector<int> out;
  for (int k = 0; k < p.phases(); ++k) {
    const int ph = (first + k) % p.phases();
    if (!std::isfinite(p.front_height[ph])) break;
    out.push_back(ph);
  }
  return out;
}

FrontStates frontStates(const PhaseProfiles& p, const std::vector<int>& phases, int rows, int gap,
                        int block) {
  const PhaseFields& f = block < 0 ? p.pooled : p.blocks[static_cast<std::size_t>(block)];
  auto value = [&](const std::vector<double>& profile, int ph, int j) {
    return profile[f.row(ph, j)];
  };
  FrontStates s;
  double n_a = 0, n_b = 0;
  for (int ph : phases) {
    const double dz = p.z[1] - p.z[0];
    const int jf = static_cast<int>(std::lround((p.front_height[ph] - p.z[0]) / dz));
    for (int side = 0; side < 2; ++side) {
      double w = 0, wT = 0, wu = 0, sum_nu = 0;
      int count = 0;
      for (int r = 0; r < rows; ++r) {
        const int j = side == 0 ? jf + gap + r : jf - gap - r;
        if (j < 0 || j >= p.rows()) continue;
        const double a = value(f.profile_area_fraction, ph, j);
        const double T = value(f.profile_temperature, ph, j);
        const double u = value(f.profile_velocity_z, ph, j);
        if (!(std::isfinite(a) && std::isfinite(T) && std::isfinite(u)) || a <= 0) continue;
        w += a;
        wT += a * T;
        wu += a * u;
        sum_nu += a;
        ++count;
      }
      if (count == 0 || w <= 0) continue;
      GasSample& g = side == 0 ? s.ahead : s.behind;
      g.nu += sum_nu / count;
      g.T += wT / w;
      g.uz += wu / w;
      (side == 0 ? n_a : n_b) += 1;
    }
  }
  if (n_a > 0) s.ahead = {s.ahead.nu / n_a, s.ahead.T / n_a, s.ahead.uz / n_a, true};
  if (n_b > 0) s.behind = {s.behind.nu / n_b, s.behind.T / n_b, s.behind.uz / n_b, true};
  s.phases = static_cast<int>(phases.size());
  return s;
}

}  // namespace granwave
