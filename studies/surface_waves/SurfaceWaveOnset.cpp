#include "studies/surface_waves/SurfaceWaveOnset.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace granwave {

namespace {

double shareError(double w, int n) {
  return n > 0 ? std::sqrt(std::max(w * (1 - w), 0.25 / n) / n) : 0.5;
}

}  // namespace

SurfaceWaveOnset waveOnset(const std::vector<double>& gammas, int variant, double f, double width_d,
                           bool periodic, const std::vector<SurfaceWaveSummary>& points) {
  SurfaceWaveOnset o;
  o.variant = variant;
  o.frequency = f;
  o.width_d = width_d;
  o.periodic = periodic;
  std::vector<const SurfaceWaveSummary*> curve;
  for (double g : gammas)
    for (const SurfaceWaveSummary& s : points)
      if (s.point.variant == variant && s.point.frequency == f && s.point.width_d == width_d &&
          s.point.periodic == periodic && s.point.gamma == g && s.ok > 0)
        curve.push_back(&s);
  if (curve.empty()) {
    o.bound = "no runs";
    return o;
  }
  if (curve.front()->waves()) {
    o.bound = "< " + formatCompact(curve.front()->point.gamma);
    return o;
  }
  for (std::size_t i = 1; i < curve.size(); ++i) {
    const SurfaceWaveSummary &a = *curve[i - 1], &b = *curve[i];
    if (!b.waves()) continue;
    const double ga = a.point.gamma, gb = b.point.gamma;
    const double wa = a.wave_fraction, wb = b.wave_fraction;
    const double t = (0.5 - wa) / (wb - wa);
    const double g = ga + t * (gb - ga);
    // d g / d wa = (gb - ga) (t - 1) / (wb - wa), d g / d wb = -(gb - ga) t / (wb - wa).
    const double ea = shareError(wa, a.windows) * (gb - ga) * (1 - t) / (wb - wa);
    const double eb = shareError(wb, b.windows) * (gb - ga) * t / (wb - wa);
    double err = std::hypot(ea, eb);
    if (wa == 0 || wb == 1) err = std::hypot(err, (gb - ga) / std::sqrt(12.0));
    o.gamma_c = {g, std::min(err, (gb - ga) / 2)};
    return o;
  }
  o.bound = "> " + formatCompact(curve.back()->point.gamma);
  return o;
}

namespace {

std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> idx(v.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < idx.size();) {
    std::size_t j = i;
    while (j + 1 < idx.size() && v[idx[j + 1]] == v[idx[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) r[idx[k]] = 0.5 * (i + j) + 1;
    i = j + 1;
  }
  return r;
}

}  // namespace

std::vector<SurfaceWaveOnset> waveOnsets(const SurfaceWavesConfig& c,
                                         const std::vector<SurfaceWaveSummary>& points) {
  std::vector<SurfaceWaveOnset> out;
  for (std::size_t v = 0; v < c.variants.size(); ++v)
    for (double f : c.frequencies)
      out.push_back(waveOnset(c.gammas, static_cast<int>(v), f, c.width_d, c.periodic, points));
  return out;
}

std::vector<VariantDissipation> variantDissipation(const SurfaceWavesConfig& c,
                                                   const std::vector<SurfaceWaveSummary>& points,
                                                   const std::vector<SurfaceWaveOnset>& onsets) {
  std::vector<VariantDissipation> out;
  const double f = c.frequencies.front();
  for (std::size_t v = 0; v < c.variants.size(); ++v) {
    VariantDissipation d;
    d.variant = static_cast<int>(v);
    for (const SurfaceWaveSummary& s : points)
      if (s.point.variant == d.variant && s.point.frequency == f &&
          s.point.gamma == c.dissipation_gamma) {
        d.e_eff = s.e_eff;
        d.loss_per_cycle = s.loss_per_cycle;
      }
    for (const SurfaceWaveOnset& o : onsets)
      if (o.variant == d.variant && o.frequency == f) {
        d.gamma_c = o.gamma_c;
        d.gamma_c_bound = o.bound;
      }
    out.push_back(d);
  }
  return out;
}

void rankCorrelation(const std::vector<VariantDissipation>& d, double& rho, int& count) {
  std::vector<double> g, e;
  for (const VariantDissipation& v : d)
    if (v.gamma_c.valid() && v.e_eff.valid())
      g.push_back(v.gamma_c.value), e.push_back(v.e_eff.value);
  count = static_cast<int>(g.size());
  rho = NAN;
  if (count < 3) return;
  const auto rg = ranks(g), re = ranks(e);
  const double mean = 0.5 * (count + 1);
  double num = 0, sg = 0, se = 0;
  for (int i = 0; i < count; ++i) {
    num += (rg[i] - mean) * (re[i] - mean);
    sg += (rg[i] - mean) * (rg[i] - mean);
    se += (re[i] - mean) * (re[i] - mean);
  }
  rho = (sg > 0 && se > 0) ? num / std::sqrt(sg * se) : NAN;
}

}  // namespace granwave
