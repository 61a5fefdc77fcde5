#include "studies/effective_restitution/EffectiveRestitutionAnalysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "coarse_grain/FieldsReader.hpp"
#include "scene/SceneDerived.hpp"
#include "studies/contract/StudyResults.hpp"
#include "studies/hydro_run/HydroModel.hpp"
#include "studies/run_files/HydroRunFile.hpp"
#include "studies/run_files/RunOutputs.hpp"

namespace granwave {

namespace {

const std::string kRoot = "/results/effective_restitution";

// Energy-weighted e_eff^2 = 1 - loss/impact of the pair collisions, over blocks of the steady
// part (the first fifth of the run is discarded, as for the summary's period).
Measurement collisionStatistics(const RunObservables& o, int blocks) {
  const std::size_t n = o.pair_impact_energy.size();
  if (n < 10) return {};
  const std::size_t first = n / 5;
  std::vector<Measurement> per_block;
  std::vector<double> values;
  for (int b = 0; b < blocks; ++b) {
    const std::size_t i0 = first + (n - 1 - first) * b / blocks;
    const std::size_t i1 = first + (n - 1 - first) * (b + 1) / blocks;
    const double impact = o.pair_impact_energy[i1] - o.pair_impact_energy[i0];
    const double loss = o.pair_impact_loss[i1] - o.pair_impact_loss[i0];
    if (impact > 0) values.push_back(std::sqrt(std::max(0.0, 1.0 - loss / impact)));
  }
  for (double v : values) per_block.push_back({v, NAN});
  return combine(per_block);  // mean and standard error over the blocks
}

// Share of the pair collisions made elastic by the TC model while theta was in [lo, hi].
double tcShare(const RunObservables& o, const std::vector<double>& theta, double lo, double hi) {
  std::size_t first = theta.size(), last = 0;
  for (std::size_t i = 0; i < theta.size() && i < o.pair_count.size(); ++i)
    if (theta[i] >= lo && theta[i] <= hi) {
      first = std::min(first, i);
      last = i;
    }
  if (first >= last) return NAN;
  const double pairs = o.pair_count[last] - o.pair_count[first];
  return pairs > 0 ? (o.tc_elastic_count[last] - o.tc_elastic_count[first]) / pairs : 0.0;
}

// What every law's analysis shares: the dry scene's temperature scale, mass and diameter (the
// Maxwell-averaged theory and the cooling fits are evaluated on the same scale for both laws).
struct Scale {
  double theta0, mass, diameter;
};

double theoryAt(const hydro::RestitutionClosure& law, double theta) {
  return std::sqrt(std::max(0.0, 1.0 - law.phiW(theta)));
}

// The layer's area-fraction weighted temperature over the window and its lowest and highest
// value over the phases, T / T0; false if the fields hold no particles.
bool layerTemperature(const FieldsRecord& r, double& mean, double& low, double& high) {
  const PhaseProfiles& p = r.profiles;
  double w_all = 0, wt_all = 0, lo = 1e300, hi = 0;
  for (int k = 0; k < p.phases(); ++k) {
    double w = 0, wt = 0;
    for (int j = 0; j < p.rows(); ++j) {
      const double a = p.at(p.pooled.profile_area_fraction, k, j);
      const double T = p.at(p.pooled.profile_temperature, k, j);
      if (std::isfinite(a) && std::isfinite(T)) {
        w += a;
        wt += a * T;
      }
    }
    if (w > 0) {
      lo = std::min(lo, wt / w);
      hi = std::max(hi, wt / w);
    }
    w_all += w;
    wt_all += wt;
  }
  if (!(w_all > 0 && hi > 0)) return false;
  mean = wt_all / w_all / r.context.T0;
  low = lo / r.context.T0;
  high = hi / r.context.T0;
  return true;
}

// (2) Collision statistics and the layer's temperature, from the driven runs; returns the
// fields of the first finished seed (for the hydro fit).
std::optional<FieldsRecord> drivenEstimates(const EffectiveRestitutionConfig& c, const RunSet& runs,
                                            int law, LawRestitution& out) {
  std::vector<Measurement> stats;
  std::vector<double> t_layer, t_lo, t_hi;
  std::optional<FieldsRecord> fields;
  for (int seed : c.seeds) {
    const RunRecord& r = runs.get(EffectiveRestitutionConfig::drivenLabel(law, seed));
    if (!r.ok) continue;
    stats.push_back(collisionStatistics(readRunObservables(r.runPath()), c.blocks));
    FieldsRecord p = readFieldsFile(r.fieldsPath());
    double mean = 0, low = 0, high = 0;
    if (layerTemperature(p, mean, low, high)) {
      t_layer.push_back(mean);
      t_lo.push_back(low);
      t_hi.push_back(high);
    }
    if (!fields) fields = std::move(p);
  }
  out.collision_statistics = combine(stats);
  out.layer_temperature = t_layer.empty() ? NAN : 0.0;
  for (double x : t_layer) out.layer_temperature += x / static_cast<double>(t_layer.size());
  out.layer_low = t_lo.empty() ? NAN : *std::min_element(t_lo.begin(), t_lo.end());
  out.layer_high = t_hi.empty() ? NAN : *std::max_element(t_hi.begin(), t_hi.end());
  return fields;
}

// (1) Free cooling of one run: over the whole range and over logarithmic temperature ranges.
CoolingRun coolingRun(const EffectiveRestitutionConfig& c, const RunSet& runs, int law, double nu,
                      bool rough, const Scale& s, const hydro::RestitutionClosure& closure) {
  CoolingRun out;
  out.nu = nu;
  out.rough = rough;
  out.mu = rough ? c.scenes.base[law].contact.friction : 0.0;
  const RunRecord& r = runs.get(EffectiveRestitutionConfig::coolingLabel(law, nu, rough));
  if (!r.ok) {
    out.failure = r.message;
    return out;
  }
  const RunObservables o = readRunObservables(r.runPath());
  const double d = s.diameter, n = 4 * nu / (std::numbers::pi * d * d);
  std::vector<double> theta;
  for (double ke : o.kinetic_energy) theta.push_back(ke / (c.cooling_count * s.mass));
  const double lo = c.cooling_t_end * s.theta0, hi = c.cooling_t_start * s.theta0;
  out.all = fitCooling(o.time, theta, nu, n, d, lo, hi);
  for (const CoolingFit& b :
       fitCoolingByTemperature(o.time, theta, nu, n, d, lo, hi, c.cooling_bins)) {
    if (!b.e_eff.valid()) continue;
    out.ranges.push_back(b);
    out.temperature.push_back(b.theta / s.theta0);
    out.theory.push_back(theoryAt(closure, b.theta));
    out.tc_share.push_back(tcShare(o, theta, b.theta_low, b.theta_high));
  }
  return out;
}

// The block values of the area fraction at phase k/M of every cycle of the window, row j.
std::vector<double> blockValues(const FieldsRecord& p, int k, int j) {
  const int M = p.profiles.phases() / p.cycles_per_window;
  std::vector<double> out;
  for (int c = 0; c < p.cycles_per_window; ++c)
    for (const PhaseFields& b : p.profiles.blocks)
      out.push_back(b.profile_area_fraction[b.row(c * M + k, j)]);
  return out;
}

// The particles' area fraction folded onto one cycle, [phase][row], with the variance of the
// mean from the blocks (at least 1e-6).
void foldedAreaFraction(const FieldsRecord& p, std::vector<double>& mean,
                        std::vector<double>& var) {
  const int M = p.profiles.phases() / p.cycles_per_window, Z = p.profiles.rows();
  mean.assign(static_cast<std::size_t>(M) * Z, 0.0);
  var.assign(mean.size(), 0.0);
  for (int k = 0; k < M; ++k)
    for (int j = 0; j < Z; ++j) {
      double s = 0, s2 = 0;
      int cnt = 0;
      for (double v : blockValues(p, k, j)) {
        if (!std::isfinite(v)) continue;
        s += v;
        s2 += v * v;
        ++cnt;
      }
      const std::size_t i = static_cast<std::size_t>(k) * Z + j;
      mean[i] = cnt ? s / cnt : 0.0;
      var[i] = cnt > 1 ? std::max((s2 - s * s / cnt) / (cnt - 1) / cnt, 1e-6) : 1e-6;
    }
}

// chi^2 of one hydro run against the folded particle profile and the cells used; false if the
// run's grid or phases do not match. Particle phase k/M pairs with hydro sample (k/M) = index
// k - 1 (hydro samples k/M for k = 1..M).
bool hydroChi2(const HydroRunContent& run, int M, int Z, const std::vector<double>& ed,
               const std::vector<double>& var, double& chi2, int& used) {
  const PhaseProfiles& h = run.lab;
  const int cycles = run.windowCycles();
  if (h.rows() != Z || h.phases() != cycles * M) return false;
  chi2 = 0;
  used = 0;  // cells where either side has particles (empty rows carry no information)
  for (int k = 0; k < M; ++k)
    for (int j = 0; j < Z; ++j) {
      double v = 0;
      for (int c = 0; c < cycles; ++c) {
        const int hk = ((c * M + k - 1) % (cycles * M) + cycles * M) % (cycles * M);
        const double a = h.at(h.pooled.profile_area_fraction, hk, j);
        v += std::isfinite(a) ? a : 0.0;
      }
      v /= cycles;
      const std::size_t i = static_cast<std::size_t>(k) * Z + j;
      if (!(v > 0 || ed[i] > 0)) continue;
      chi2 += (v - ed[i]) * (v - ed[i]) / var[i];
      ++used;
    }
  return true;
}

// The minimum of chi^2(e): a parabola through the three points around the lowest one; the
// error from Delta chi^2 = 1, scaled by sqrt(chi^2/dof) when the model misses the data.
void parabolaMinimum(const std::vector<int>& dof, HydroFit& fit) {
  const std::vector<double>& fe = fit.e;
  const std::vector<double>& fchi = fit.chi2;
  const auto best = std::min_element(fchi.begin(), fchi.end());
  if (best == fchi.end() || fe.size() < 3) return;
  std::size_t i = static_cast<std::size_t>(best - fchi.begin());
  i = std::clamp<std::size_t>(i, 1, fe.size() - 2);
  const double x0 = fe[i - 1], x1 = fe[i], x2 = fe[i + 1];
  const double y0 = fchi[i - 1], y1 = fchi[i], y2 = fchi[i + 1];
  const double den = (x0 - x1) * (x0 - x2) * (x1 - x2);
  const double A = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / den;
  const double B = (x2 * x2 * (y0 - y1) + x1 * x1 * (y2 - y0) + x0 * x0 * (y1 - y2)) / den;
  fit.chi2_per_dof = *best / dof[static_cast<std::size_t>(best - fchi.begin())];
  if (A > 0) {
    const double xmin = std::clamp(-B / (2 * A), fe.front(), fe.back());
    fit.best = {xmin, std::sqrt(1.0 / A) * std::sqrt(std::max(1.0, fit.chi2_per_dof))};
  } else {
    fit.best = {fe[static_cast<std::size_t>(best - fchi.begin())], NAN};
  }
}

// (3) Constant-e hydro fitted to the particles' area-fraction profiles, folded onto one cycle.
HydroFit hydroFit(const EffectiveRestitutionConfig& c, const RunSet& runs, const FieldsRecord& p) {
  HydroFit fit;
  const int M = p.profiles.phases() / p.cycles_per_window, Z = p.profiles.rows();
  std::vector<double> ed, var;
  foldedAreaFraction(p, ed, var);
  std::vector<int> dof;
  for (double e : c.hydro_e) {
    const RunRecord& r = runs.get(EffectiveRestitutionConfig::hydroLabel(e));
    if (!r.ok) continue;
    double chi2 = 0;
    int used = 0;
    if (!hydroChi2(readHydroRunFile(r.hydroPath()), M, Z, ed, var, chi2, used)) continue;
    fit.e.push_back(e);
    fit.chi2.push_back(chi2);
    dof.push_back(std::max(1, used - 1));
  }
  parabolaMinimum(dof, fit);
  return fit;
}

// Can one constant describe the law? The largest distance between the three estimates.
void disagreement(LawRestitution& l) {
  const std::vector<Measurement> three{l.free_cooling, l.collision_statistics, l.hydro.best};
  double worst = 0;
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t b = a + 1; b < 3; ++b) {
      const double z = sigmaDistance(three[a], three[b]);
      if (!std::isfinite(z)) continue;
      worst = std::max(worst, std::abs(z));
      ++l.compared;
    }
  l.largest_disagreement = l.compared == 0 ? NAN : worst;
}

LawRestitution analyseLaw(const EffectiveRestitutionConfig& c, const RunSet& runs, int law,
                          const Scale& s) {
  LawRestitution l;
  const hydro::RestitutionClosure closure = restitutionClosure(c.scenes.base[law]);
  for (int k = 0; k <= 60; ++k) {
    const double x = c.cooling_t_end * 0.5 * std::pow(4.0 / (c.cooling_t_end * 0.5), k / 60.0);
    l.theory_temperature.push_back(x);
    l.theory_e.push_back(theoryAt(closure, x * s.theta0));
  }
  const std::optional<FieldsRecord> fields = drivenEstimates(c, runs, law, l);
  l.theory_at_layer = theoryAt(closure, l.layer_temperature * s.theta0);
  l.theory_at_low = theoryAt(closure, l.layer_low * s.theta0);
  l.theory_at_high = theoryAt(closure, l.layer_high * s.theta0);
  for (int rough = 0; rough < 2; ++rough) {
    std::vector<Measurement> all;
    for (double nu : c.cooling_nu) {
      l.cooling.push_back(coolingRun(c, runs, law, nu, rough, s, closure));
      if (l.cooling.back().failure.empty()) all.push_back(l.cooling.back().all.e_eff);
    }
    (rough ? l.free_cooling_with_friction : l.free_cooling) = combine(all);
  }
  if (fields) l.hydro = hydroFit(c, runs, *fields);
  disagreement(l);
  return l;
}

void writeLaw(h5::File& f, const std::string& grp, const LawRestitution& l) {
  f.createGroup(grp);
  putSeries(f, grp + "/theory_temperature_over_T0", l.theory_temperature, "1");
  putSeries(f, grp + "/theory_e_eff", l.theory_e, "1");
  putMeasurement(f, grp, "collision_statistics", l.collision_statistics);
  putValue(f, grp, "layer_temperature_over_T0", l.layer_temperature);
  putValue(f, grp, "layer_temperature_min_over_T0", l.layer_low);
  putValue(f, grp, "layer_temperature_max_over_T0", l.layer_high);
  putValue(f, grp, "theory_at_layer_temperature", l.theory_at_layer);
  for (const CoolingRun& r : l.cooling) {
    if (!r.failure.empty()) continue;
    std::vector<double> y, e;
    for (const CoolingFit& b : r.ranges) {
      y.push_back(b.e_eff.value);
      e.push_back(b.e_eff.error);
    }
    const std::string cg =
        fmt::format("{}/cooling_{}_nu_{:g}", grp, r.rough ? "with_friction" : "smooth", r.nu);
    f.createGroup(cg);
    putSeries(f, cg + "/temperature_over_T0", r.temperature, "1");
    putSeries(f, cg + "/e_eff", y, "1");
    putSeries(f, cg + "/e_eff_error", e, "1");
    putMeasurement(f, cg, "e_eff_all", r.all.e_eff);
  }
  putMeasurement(f, grp, "free_cooling", l.free_cooling);
  putMeasurement(f, grp, "free_cooling_with_friction", l.free_cooling_with_friction);
  putMeasurement(f, grp, "hydro_fit", l.hydro.best);
  putValue(f, grp, "hydro_fit_chi2_per_dof", l.hydro.chi2_per_dof);
  putSeries(f, grp + "/hydro_fit_e", l.hydro.e, "1");
  putSeries(f, grp + "/hydro_fit_chi2", l.hydro.chi2, "1");
  putValue(f, grp, "largest_disagreement_sigma", l.largest_disagreement);
}

}  // namespace

EffectiveRestitutionResults analyseEffectiveRestitution(const EffectiveRestitutionConfig& c,
                                                        const RunSet& runs) {
  const SceneDerived dv = derive(c.scenes.base[0]);
  const Scale s{0.5 * dv.v0 * dv.v0, dv.mass, c.scenes.base[0].particles.diameter};
  EffectiveRestitutionResults r;
  for (int law = 0; law < kLaws; ++law) r.law[law] = analyseLaw(c, runs, law, s);
  return r;
}

void writeEffectiveRestitutionResults(h5::File& f, const EffectiveRestitutionResults& r) {
  f.createGroup(kRoot);
  for (int law = 0; law < kLaws; ++law)
    writeLaw(f, fmt::format("{}/{}", kRoot, kLawNames[law]), r.law[law]);
}

}  // namespace granwave
