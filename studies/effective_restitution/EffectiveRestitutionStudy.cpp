#include "studies/effective_restitution/EffectiveRestitutionStudy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "scene/SceneDerived.hpp"
#include "studies/effective_restitution/CoolingFit.hpp"
#include "studies/framework/Measurement.hpp"
#include "studies/run_files/HydroRunFile.hpp"
#include "studies/run_files/RunOutputs.hpp"
#include "studies/framework/StudyResults.hpp"
#include "studies/framework/StudyScenes.hpp"

namespace granwave {

namespace {

const char* kLaw[2] = {"dry", "wet"};
const char* kColor[2] = {"tab:orange", "tab:blue"};
const std::string kRoot = "/results/effective_restitution";

std::string g(double v) { return fmt::format("{:g}", v); }

struct Config {
  std::string path[2];
  std::vector<std::string> set;
  double duration = 30;
  std::vector<int> seeds{1, 2, 3};
  int window = 2, blocks = 5;
  std::vector<double> cooling_nu{0.2, 0.4, 0.6};
  int cooling_count = 1000;
  double cooling_t_start = 1.0;  // initial T / T0
  double cooling_t_end = 0.02;   // lowest T / T0 fitted
  double cooling_duration = 1.0, cooling_record = 0.001;
  int cooling_bins = 6;
  std::vector<double> hydro_e{0.5, 0.6, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95};
};

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

class EffectiveRestitutionStudy final : public Study {
 public:
  explicit EffectiveRestitutionStudy(StudyFile& f);
  std::string title() const override {
    return "Effective restitution: can one constant stand for the velocity-dependent laws?";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  void analyse(const RunSet& runs, h5::File& f, Report& report) const override;

 private:
  std::string coolingLabel(int law, double nu, bool rough) const {
    return fmt::format("ED {} cooling nu={}{}", kLaw[law], g(nu), rough ? " with friction" : "");
  }
  std::string drivenLabel(int law, int seed) const {
    return fmt::format("ED {} seed {}", kLaw[law], seed);
  }
  std::string hydroLabel(double e) const { return fmt::format("hydro constant e={}", g(e)); }

  const StudyFile* file_;
  Config c_;
  Scene base_[2];
  std::vector<RunRequest> requests_;
};

EffectiveRestitutionStudy::EffectiveRestitutionStudy(StudyFile& f) : file_(&f) {
  c_.path[0] = f.scenePath("scenes", "dry", "../scenes/paper-dry.toml");
  c_.path[1] = f.scenePath("scenes", "wet", "../scenes/paper-wet.toml");
  c_.set = f.strings("scenes", "set", {});
  c_.duration = f.number("driven", "duration", c_.duration);
  c_.seeds = f.integers("driven", "seeds", c_.seeds);
  c_.window = f.integer("driven", "window_cycles", c_.window);
  c_.blocks = f.integer("driven", "blocks", c_.blocks);
  c_.cooling_nu = f.numbers("cooling", "area_fractions", c_.cooling_nu);
  c_.cooling_count = f.integer("cooling", "count", c_.cooling_count);
  c_.cooling_t_start = f.number("cooling", "initial_temperature", c_.cooling_t_start);
  c_.cooling_t_end = f.number("cooling", "lowest_temperature", c_.cooling_t_end);
  c_.cooling_duration = f.number("cooling", "duration", c_.cooling_duration);
  c_.cooling_record = f.number("cooling", "record_interval", c_.cooling_record);
  c_.cooling_bins = f.integer("cooling", "temperature_bins", c_.cooling_bins);
  c_.hydro_e = f.numbers("hydro_fit", "e", c_.hydro_e);
  for (double nu : c_.cooling_nu)
    if (!(nu > 0 && nu < 0.8)) f.fail("cooling", "area_fractions", "expected values in (0, 0.8)");
  if (!(c_.cooling_t_end > 0 && c_.cooling_t_end < c_.cooling_t_start))
    f.fail("cooling", "lowest_temperature", "expected 0 < lowest < initial_temperature");
  if (c_.hydro_e.size() < 3) f.fail("hydro_fit", "e", "expected at least 3 values to fit");
  for (double e : c_.hydro_e)
    if (!(e > 0 && e <= 1)) f.fail("hydro_fit", "e", "expected values in (0, 1]");

  for (int law = 0; law < 2; ++law) {
    base_[law] = studyScene(f, c_.path[law], c_.set);
    const SceneDerived dv = derive(base_[law]);
    for (int seed : c_.seeds) {
      std::vector<std::string> o = c_.set;
      o.push_back(fmt::format("run.seed={}", seed));
      o.push_back(fmt::format("run.duration={}", g(c_.duration)));
      RunRequest q =
          runRequest(RunKind::Particles, drivenLabel(law, seed), studyScene(f, c_.path[law], o));
      q.window_cycles = c_.window;
      q.blocks = c_.blocks;
      requests_.push_back(std::move(q));
    }
    // Free cooling in a fully periodic square box at the layer's densities, no gravity.
    const double d = base_[law].particles.diameter;
    for (double nu : c_.cooling_nu)
      for (int rough = 0; rough < 2; ++rough) {
        const double side = std::sqrt(c_.cooling_count * std::numbers::pi * d * d / (4 * nu));
        std::vector<std::string> o = c_.set;
        for (const std::string& s :
             {std::string("container.periodic_x=true"), std::string("container.periodic_z=true"),
              std::string("drive.frequency=0"), std::string("run.gravity=0"),
              fmt::format("particles.count={}", c_.cooling_count),
              fmt::format("container.width={:.9g}", side),
              fmt::format("container.height={:.9g}", side),
              fmt::format("initial.temperature={:.9g}", c_.cooling_t_start * dv.T0),
              std::string("initial.placement=\"lattice\""),
              fmt::format("run.record_interval={}", g(c_.cooling_record)),
              fmt::format("run.duration={}", g(c_.cooling_duration)),
              fmt::format("run.seed={}", c_.seeds.front())})
          o.push_back(s);
        if (!rough) o.push_back("contact.friction=0");
        RunRequest q = runRequest(RunKind::Particles, coolingLabel(law, nu, rough),
                                  studyScene(f, c_.path[law], o));
        q.fields = false;
        requests_.push_back(std::move(q));
      }
  }
  // Constant-e hydro: the law's parameters do not enter, so the dry scene serves both.
  for (double e : c_.hydro_e) {
    std::vector<std::string> o = c_.set;
    o.push_back("hydro.restitution_model=\"constant\"");
    o.push_back(fmt::format("contact.e={}", g(e)));
    requests_.push_back(runRequest(RunKind::Hydro, hydroLabel(e), studyScene(f, c_.path[0], o)));
  }
}

void EffectiveRestitutionStudy::analyse(const RunSet& runs, h5::File& f, Report& report) const {
  f.createGroup(kRoot);
  const double d = base_[0].particles.diameter;
  const SceneDerived dv = derive(base_[0]);
  const double theta0 = 0.5 * dv.v0 * dv.v0;  // T0 / m

  ReportSection& intro = report.section(
      "Three fits against the theory",
      "The Maxwell-averaged theory gives the effective restitution of a velocity-dependent law "
      "at temperature T as e_eff(T) = sqrt(1 - <1 - e^2>), the energy-weighted average over "
      "the impact speeds of a Maxwellian (hydro/RestitutionClosure.hpp). It is fitted here to "
      "the particles in three ways: (1) free cooling of a homogeneous periodic gas at the "
      "layer's densities (Haff's law, theta^(-1/2) linear in t, fitted over temperature "
      "ranges); (2) the energy-weighted collision statistics of the driven run, e_eff^2 = 1 - "
      "(energy lost) / (normal impact energy) of the pair collisions, over blocks of the steady "
      "run; (3) the constant-e hydro solver fitted to the particles' area-fraction profiles "
      "over a cycle (least squares weighted by the block variance).");

  Figure fig;
  fig.title = "e_eff against temperature";
  fig.caption =
      "Lines: Maxwell-averaged theory for the dry and wet laws. Points: free-cooling fits per "
      "temperature range (markers by area fraction). Squares: collision statistics of the "
      "driven run at the layer's mean temperature (horizontal bar: the range of the layer's "
      "mean temperature over the cycle). Dashed: the constant-e hydro fit.";
  fig.xlabel = "T / T0";
  fig.ylabel = "e_eff";
  fig.xscale = "log";
  Table t;
  t.title = "One constant e_eff, three ways";
  t.caption = "One sigma errors. Theory: e_eff at the layer's mean temperature.";
  t.columns = {"layer",
               "theory at layer T",
               "free cooling, mu = 0",
               "free cooling, scene's mu",
               "collision statistics",
               "hydro fit to fields",
               "hydro fit chi^2/dof"};
  Table tc;
  tc.title = "Free cooling by temperature range";
  tc.columns = {"layer",
                "mu",
                "area fraction",
                "T / T0",
                "e_eff (cooling)",
                "e_eff (theory)",
                "TC-elastic share of the range's collisions"};
  std::string verdict;

  for (int law = 0; law < 2; ++law) {
    const hydro::RestitutionClosure law_closure = restitutionClosure(base_[law]);
    // Theory curve.
    std::vector<double> tt, te;
    for (int k = 0; k <= 60; ++k) {
      const double x = c_.cooling_t_end * 0.5 * std::pow(4.0 / (c_.cooling_t_end * 0.5), k / 60.0);
      tt.push_back(x);
      te.push_back(std::sqrt(std::max(0.0, 1.0 - law_closure.phiW(x * theta0))));
    }
    fig.series.push_back(lineSeries(tt, te, std::string("theory, ") + kLaw[law], kColor[law]));
    const std::string grp = fmt::format("{}/{}", kRoot, kLaw[law]);
    f.createGroup(grp);
    putSeries(f, grp + "/theory_temperature_over_T0", tt, "1");
    putSeries(f, grp + "/theory_e_eff", te, "1");

    // (2) Collision statistics and the layer's temperature, from the driven runs.
    std::vector<Measurement> stats;
    std::vector<double> t_layer, t_lo, t_hi;
    std::optional<ParticleFields> fields;
    for (int seed : c_.seeds) {
      const RunRecord& r = runs.get(drivenLabel(law, seed));
      if (!r.ok) continue;
      stats.push_back(collisionStatistics(readRunObservables(r.runPath()), c_.blocks));
      ParticleFields p = readParticleFields(r.fieldsPath());
      double w_all = 0, wt_all = 0, lo = 1e300, hi = 0;
      for (int k = 0; k < p.phases; ++k) {
        double w = 0, wt = 0;
        for (int j = 0; j < p.nz; ++j) {
          const double a = p.at(p.area_fraction, k, j), T = p.at(p.temperature, k, j);
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
      if (w_all > 0 && hi > 0) {
        t_layer.push_back(wt_all / w_all / p.T0);
        t_lo.push_back(lo / p.T0);
        t_hi.push_back(hi / p.T0);
      }
      if (!fields) fields = std::move(p);
    }
    const Measurement e_stats = combine(stats);
    double layer_T = t_layer.empty() ? NAN : 0.0;
    for (double x : t_layer) layer_T += x / static_cast<double>(t_layer.size());
    const double layer_lo = t_lo.empty() ? NAN : *std::min_element(t_lo.begin(), t_lo.end());
    const double layer_hi = t_hi.empty() ? NAN : *std::max_element(t_hi.begin(), t_hi.end());
    const double theory_at_layer =
        std::sqrt(std::max(0.0, 1.0 - law_closure.phiW(layer_T * theta0)));
    Series ss = errorSeries({layer_T}, {e_stats.value}, {e_stats.error},
                            std::string("collision statistics, ") + kLaw[law], kColor[law]);
    ss.marker = "s";
    ss.xerr = {0.5 * (layer_hi - layer_lo)};
    ss.x = {0.5 * (layer_hi + layer_lo)};
    fig.series.push_back(ss);
    putMeasurement(f, grp, "collision_statistics", e_stats);
    putValue(f, grp, "layer_temperature_over_T0", layer_T);
    putValue(f, grp, "layer_temperature_min_over_T0", layer_lo);
    putValue(f, grp, "layer_temperature_max_over_T0", layer_hi);
    putValue(f, grp, "theory_at_layer_temperature", theory_at_layer);

    // (1) Free cooling, with the normal law alone (mu = 0: what the theory describes) and with
    // the scene's friction (rotation takes translational energy too).
    Measurement cooling_by_friction[2];
    const char* markers[] = {"o", "^", "v", "D", "P"};
    for (int rough = 0; rough < 2; ++rough) {
      std::vector<Measurement> cooling_all;
      int mi = 0;
      for (double nu : c_.cooling_nu) {
        const RunRecord& r = runs.get(coolingLabel(law, nu, rough));
        const std::string mu = rough ? g(base_[law].contact.friction) : "0";
        if (!r.ok) {
          tc.rows.push_back({kLaw[law], mu, g(nu), "–", "failed: " + r.message, "–", "–"});
          continue;
        }
        const RunObservables o = readRunObservables(r.runPath());
        const double m = dv.mass, n = 4 * nu / (std::numbers::pi * d * d);
        std::vector<double> theta;
        for (double ke : o.kinetic_energy) theta.push_back(ke / (c_.cooling_count * m));
        const double lo = c_.cooling_t_end * theta0, hi = c_.cooling_t_start * theta0;
        const CoolingFit all = fitCooling(o.time, theta, nu, n, d, lo, hi);
        cooling_all.push_back(all.e_eff);
        std::vector<double> x, y, e;
        for (const CoolingFit& b :
             fitCoolingByTemperature(o.time, theta, nu, n, d, lo, hi, c_.cooling_bins)) {
          if (!b.e_eff.valid()) continue;
          x.push_back(b.theta / theta0);
          y.push_back(b.e_eff.value);
          e.push_back(b.e_eff.error);
          tc.rows.push_back(
              {kLaw[law], mu, g(nu), formatNumber(b.theta / theta0, 3), format(b.e_eff, 3),
               formatNumber(std::sqrt(std::max(0.0, 1.0 - law_closure.phiW(b.theta))), 3),
               formatNumber(tcShare(o, theta, b.theta_low, b.theta_high), 2)});
        }
        Series cs =
            errorSeries(x, y, e, fmt::format("cooling {}, mu = {}, nu = {:g}", kLaw[law], mu, nu),
                        rough ? "grey" : kColor[law]);
        cs.marker = markers[mi++ % 5];
        cs.linestyle = "none";
        fig.series.push_back(cs);
        const std::string cg =
            fmt::format("{}/cooling_{}_nu_{:g}", grp, rough ? "with_friction" : "smooth", nu);
        f.createGroup(cg);
        putSeries(f, cg + "/temperature_over_T0", x, "1");
        putSeries(f, cg + "/e_eff", y, "1");
        putSeries(f, cg + "/e_eff_error", e, "1");
        putMeasurement(f, cg, "e_eff_all", all.e_eff);
      }
      cooling_by_friction[rough] = combine(cooling_all);
    }
    const Measurement e_cooling = cooling_by_friction[0];
    putMeasurement(f, grp, "free_cooling", e_cooling);
    putMeasurement(f, grp, "free_cooling_with_friction", cooling_by_friction[1]);

    // (3) Constant-e hydro fitted to the particles' area-fraction profiles, folded onto one
    // cycle. Particle phase k/M pairs with hydro sample (k/M) = index k - 1 (hydro samples
    // k/M for k = 1..M).
    Measurement e_fit;
    double chi2_dof = NAN;
    std::vector<double> fe, fchi;
    std::vector<int> fdof;
    if (fields) {
      const ParticleFields& p = *fields;
      const int M = p.phases / p.cycles_per_window, Z = p.nz;
      std::vector<double> ed(static_cast<std::size_t>(M) * Z, 0.0), var(ed.size(), 0.0);
      for (int k = 0; k < M; ++k)
        for (int j = 0; j < Z; ++j) {
          double s = 0, s2 = 0;
          int cnt = 0;
          for (int c = 0; c < p.cycles_per_window; ++c)
            for (int b = 0; b < p.blocks; ++b) {
              const double v =
                  p.block_area_fraction[(static_cast<std::size_t>(b) * p.phases + c * M + k) * Z +
                                        j];
              if (!std::isfinite(v)) continue;
              s += v;
              s2 += v * v;
              ++cnt;
            }
          const std::size_t i = static_cast<std::size_t>(k) * Z + j;
          ed[i] = cnt ? s / cnt : 0.0;
          var[i] = cnt > 1 ? std::max((s2 - s * s / cnt) / (cnt - 1) / cnt, 1e-6) : 1e-6;
        }
      for (double e : c_.hydro_e) {
        const RunRecord& r = runs.get(hydroLabel(e));
        if (!r.ok) continue;
        const HydroFields h = readHydroFields(r.hydroPath());
        const int cycles = h.periodic ? h.period : 2;
        if (h.nz != Z || h.phases != cycles * M) continue;
        double chi2 = 0;
        int used = 0;  // cells where either side has particles (empty rows carry no information)
        for (int k = 0; k < M; ++k)
          for (int j = 0; j < Z; ++j) {
            double v = 0;
            for (int c = 0; c < cycles; ++c) {
              const int hk = ((c * M + k - 1) % (cycles * M) + cycles * M) % (cycles * M);
              const double a = h.at(h.area_fraction, hk, j);
              v += std::isfinite(a) ? a : 0.0;
            }
            v /= cycles;
            const std::size_t i = static_cast<std::size_t>(k) * Z + j;
            if (!(v > 0 || ed[i] > 0)) continue;
            chi2 += (v - ed[i]) * (v - ed[i]) / var[i];
            ++used;
          }
        fe.push_back(e);
        fchi.push_back(chi2);
        fdof.push_back(std::max(1, used - 1));
      }
      const auto best = std::min_element(fchi.begin(), fchi.end());
      if (best != fchi.end() && fe.size() >= 3) {
        std::size_t i = static_cast<std::size_t>(best - fchi.begin());
        i = std::clamp<std::size_t>(i, 1, fe.size() - 2);
        // Parabola through the three points around the minimum.
        const double x0 = fe[i - 1], x1 = fe[i], x2 = fe[i + 1];
        const double y0 = fchi[i - 1], y1 = fchi[i], y2 = fchi[i + 1];
        const double den = (x0 - x1) * (x0 - x2) * (x1 - x2);
        const double A = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / den;
        const double B = (x2 * x2 * (y0 - y1) + x1 * x1 * (y2 - y0) + x0 * x0 * (y1 - y2)) / den;
        chi2_dof = *best / fdof[static_cast<std::size_t>(best - fchi.begin())];
        if (A > 0) {
          const double xmin = std::clamp(-B / (2 * A), fe.front(), fe.back());
          // Delta chi^2 = 1, scaled by sqrt(chi^2/dof) when the model misses the data.
          e_fit = {xmin, std::sqrt(1.0 / A) * std::sqrt(std::max(1.0, chi2_dof))};
        } else {
          e_fit = {fe[static_cast<std::size_t>(best - fchi.begin())], NAN};
        }
      }
    }
    putMeasurement(f, grp, "hydro_fit", e_fit);
    putValue(f, grp, "hydro_fit_chi2_per_dof", chi2_dof);
    putSeries(f, grp + "/hydro_fit_e", fe, "1");
    putSeries(f, grp + "/hydro_fit_chi2", fchi, "1");
    if (e_fit.valid()) {
      Series hl = horizontalLine(e_fit.value, std::string("hydro fit, ") + kLaw[law],
                                 std::isfinite(e_fit.error) ? e_fit.error : 0, kColor[law]);
      fig.series.push_back(hl);
    }
    t.rows.push_back({kLaw[law], formatNumber(theory_at_layer, 3), format(e_cooling, 3),
                      format(cooling_by_friction[1], 3), format(e_stats, 3), format(e_fit, 3),
                      formatNumber(chi2_dof, 1)});

    // Can one constant describe the law? The three estimates must agree within 2 sigma.
    std::vector<Measurement> three{e_cooling, e_stats, e_fit};
    double worst = 0;
    int compared = 0;
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t b = a + 1; b < 3; ++b) {
        const double z = sigmaDistance(three[a], three[b]);
        if (!std::isfinite(z)) continue;
        worst = std::max(worst, std::abs(z));
        ++compared;
      }
    if (compared == 0) worst = NAN;
    const double theory_lo = std::sqrt(std::max(0.0, 1.0 - law_closure.phiW(layer_lo * theta0)));
    const double theory_hi = std::sqrt(std::max(0.0, 1.0 - law_closure.phiW(layer_hi * theta0)));
    putValue(f, grp, "largest_disagreement_sigma", worst);
    verdict += fmt::format(
        "{} law: the three estimates {} (largest disagreement {:.1f} sigma); over the layer's "
        "temperature range T/T0 = {:.3f} to {:.3f} the theory's e_eff runs from {:.3f} to "
        "{:.3f}. ",
        kLaw[law],
        compared == 0 ? "cannot be compared (runs failed)"
        : worst <= 2  ? "agree"
                      : "disagree",
        worst, layer_lo, layer_hi, theory_lo, theory_hi);
  }
  intro.add(std::move(t));
  intro.add(std::move(fig));
  intro.add(std::move(tc));
  intro.addText(verdict +
                "Free cooling in event-driven hard disks is known to run about 2 % slower than "
                "Haff-Sonine because of velocity correlations (docs/physics.md), which biases "
                "the cooling estimate of e_eff slightly upwards; late in the cooling the TC "
                "model makes a growing share of collisions elastic (table), which does the "
                "same, so the lowest temperature fitted is kept well above that regime.");
  report.summary = verdict;
}

}  // namespace

std::unique_ptr<Study> makeEffectiveRestitutionStudy(StudyFile& file) {
  return std::make_unique<EffectiveRestitutionStudy>(file);
}

}  // namespace granwave
