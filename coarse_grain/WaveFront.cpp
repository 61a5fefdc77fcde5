#include "coarse_grain/WaveFront.hpp"

#include <cmath>

#include "coarse_grain/LineFit.hpp"

namespace granwave {

std::vector<double> frontHeights(const PhaseFields& f, double z0, double dz, double T0,
                                 const FrontOptions& o, std::vector<double>* peak) {
  std::vector<double> h(f.phases, kNaN);
  if (peak) peak->assign(f.phases, kNaN);
  for (int ph = 0; ph < f.phases; ++ph) {
    int best = -1;
    double tmax = -1;
    for (int j = 0; j < f.nz; ++j) {
      const double t = f.profile_temperature[f.row(ph, j)];
      if (!(f.profile_area_fraction[f.row(ph, j)] >= o.layer_min_area_fraction)) continue;
      if (std::isfinite(t) && t > tmax) {
        tmax = t;
        best = j;
      }
    }
    if (peak && best >= 0) (*peak)[ph] = tmax / T0;
    if (best < 0 || tmax / T0 <= o.threshold) continue;
    double offset = 0;  // parabolic refinement through rows best-1, best, best+1
    if (best > 0 && best + 1 < f.nz) {
      const double a = f.profile_temperature[f.row(ph, best - 1)];
      const double c = f.profile_temperature[f.row(ph, best + 1)];
      const double den = a - 2 * tmax + c;
      if (std::isfinite(a) && std::isfinite(c) && den < 0) offset = 0.5 * (a - c) / den;
    }
    h[ph] = z0 + (best + 0.5 + offset) * dz;
  }
  return h;
}

namespace {

struct Run {
  int first, length;
};

// Maximal runs of finite entries, cyclic (a run through the last phase continues at 0).
std::vector<Run> finiteRuns(const std::vector<double>& h) {
  const int n = static_cast<int>(h.size());
  std::vector<Run> runs;
  int start = -1;
  for (int k = 0; k < n; ++k) {
    if (!std::isfinite(h[k])) {
      start = k;
      break;
    }
  }
  if (start < 0) return {{0, n}};  // a front at every phase: one run
  for (int s = 1; s <= n; ++s) {
    const int k = (start + s) % n;
    if (std::isfinite(h[k])) {
      if (runs.empty() || runs.back().first + runs.back().length != start + s)
        runs.push_back({start + s, 0});
      ++runs.back().length;
    }
  }
  for (Run& r : runs) r.first %= n;
  return runs;
}

double gasAhead(const PhaseFields& f, int ph, double front, double z0, double dz, double d_gap,
                double min_nu) {
  double num = 0, den = 0;
  for (int j = 0; j < f.nz; ++j) {
    const double z = z0 + (j + 0.5) * dz;
    if (z <= front + d_gap) continue;
    const double nu = f.profile_area_fraction[f.row(ph, j)];
    const double v = f.profile_velocity_z[f.row(ph, j)];
    if (!(nu >= min_nu) || !std::isfinite(v)) continue;
    num += nu * v;
    den += nu;
  }
  return den > 0 ? num / den : kNaN;
}

}  // namespace

std::vector<FrontEpisode> frontEpisodes(const PhaseFields& pooled,
                                        const std::vector<PhaseFields>& blocks, double z0,
                                        double dz, double T0, double phase_dt,
                                        const FrontOptions& o,
                                        const std::vector<double>& plate_height) {
  std::vector<double> peak;
  const std::vector<double> h = frontHeights(pooled, z0, dz, T0, o, &peak);
  std::vector<std::vector<double>> hb;
  for (const PhaseFields& b : blocks) hb.push_back(frontHeights(b, z0, dz, T0, o));
  const int n = pooled.phases;

  std::vector<FrontEpisode> out;
  for (const Run& run : finiteRuns(h)) {
    if (run.length < o.min_points) continue;
    FrontEpisode e;
    e.first_phase = run.first;
    e.last_phase = (run.first + run.length - 1) % n;
    if (!plate_height.empty()) {
      e.start_above_plate = h[run.first] - plate_height[run.first];
      e.from_impact = e.start_above_plate <= o.impact_max_rows * dz;
    }
    double gas_sum = 0;
    int gas_n = 0;
    for (int s = 0; s < run.length; ++s) {
      const int ph = (run.first + s) % n;
      e.time.push_back((run.first + s) * phase_dt);
      e.height.push_back(h[ph]);
      e.peak_temperature = std::max(e.peak_temperature, peak[ph]);
      const double u = gasAhead(pooled, ph, h[ph], z0, dz, dz, o.gas_min_area_fraction);
      if (std::isfinite(u)) {
        gas_sum += u;
        ++gas_n;
      }
    }
    const LineFit fit = fitLine(e.time, e.height);
    e.speed = fit.slope;
    e.fit_error = fit.slope_error;
    // The same episode in each block: its phases where that block also has a front.
    std::vector<double> slopes;
    for (const auto& bh : hb) {
      std::vector<double> t, z;
      for (int s = 0; s < run.length; ++s) {
        const int ph = (run.first + s) % n;
        if (std::isfinite(bh[ph])) {
          t.push_back((run.first + s) * phase_dt);
          z.push_back(bh[ph]);
        }
      }
      if (static_cast<int>(t.size()) >= o.min_points) slopes.push_back(fitLine(t, z).slope);
    }
    e.blocks_used = static_cast<int>(slopes.size());
    if (slopes.size() >= 2) {
      double m = 0, v = 0;
      for (double s : slopes) m += s / slopes.size();
      for (double s : slopes) v += (s - m) * (s - m) / (slopes.size() - 1);
      e.block_spread = std::sqrt(v / slopes.size());
    }
    const double fe = std::isfinite(e.fit_error) ? e.fit_error : 0.0;
    const double be = std::isfinite(e.block_spread) ? e.block_spread : 0.0;
    e.speed_error = std::sqrt(fe * fe + be * be);
    if (gas_n > 0) {
      e.gas_velocity_ahead = gas_sum / gas_n;
      e.speed_relative = e.speed - e.gas_velocity_ahead;
    }
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace granwave
