#include "studies/stability/StabilityStudy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "studies/framework/FailureReason.hpp"
#include "studies/run_files/HydroRunFile.hpp"
#include "studies/run_files/RunOutputs.hpp"
#include "studies/stability/StabilityFeatures.hpp"
#include "studies/stability/StabilityGrid.hpp"
#include "studies/framework/StudyResults.hpp"
#include "studies/framework/StudyScenes.hpp"

namespace granwave {

namespace {

const char* kLaw[2] = {"dry", "wet"};
const std::string kRoot = "/results/stability";
const std::vector<std::string> kStates{"crystal", "amorphous", "liquid-like"};
const char* kStateColor[3] = {"tab:blue", "tab:green", "tab:orange"};

std::string g(double v) { return fmt::format("{:g}", v); }

struct Config {
  std::string path[2];
  std::vector<std::string> set;
  std::vector<double> frequencies{10, 15, 20, 30};
  std::vector<double> gammas{2, 3, 4, 5, 6, 7};
  double cycles = 150;
  std::vector<int> seeds{1, 2, 3};
  int window = 2, blocks = 5;
  bool hydro = true;
  int gallery_per_state = 2;
};

class StabilityStudy final : public Study {
 public:
  explicit StabilityStudy(StudyFile& f);
  std::string title() const override {
    return "Stability diagrams of dry and wet vibrated layers (the paper's Fig. 3)";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  void analyse(const RunSet& runs, h5::File& f, Report& report) const override;

 private:
  std::string edLabel(int law, double f, double gamma, int seed) const {
    return fmt::format("ED {} f={} Gamma={} seed {}", kLaw[law], g(f), g(gamma), seed);
  }
  std::string hydroLabel(int law, double f, double gamma) const {
    return fmt::format("hydro {} f={} Gamma={}", kLaw[law], g(f), g(gamma));
  }
  StabilityGrid verdicts(const RunSet& runs) const;
  void diagrams(const StabilityGrid& grid, ReportSection& s) const;
  void gallery(const RunSet& runs, const StabilityGrid& grid, Report& report) const;
  Config c_;
  std::vector<RunRequest> requests_;
};

StabilityStudy::StabilityStudy(StudyFile& f) {
  c_.path[0] = f.scenePath("scenes", "dry", "../scenes/paper-dry.toml");
  c_.path[1] = f.scenePath("scenes", "wet", "../scenes/paper-wet.toml");
  c_.set = f.strings("scenes", "set", {});
  c_.frequencies = f.numbers("grid", "frequencies", c_.frequencies);
  c_.gammas = f.numbers("grid", "gammas", c_.gammas);
  c_.cycles = f.number("particles", "cycles", c_.cycles);
  c_.seeds = f.integers("particles", "seeds", c_.seeds);
  c_.window = f.integer("particles", "window_cycles", c_.window);
  c_.blocks = f.integer("particles", "blocks", c_.blocks);
  c_.hydro = f.boolean("hydro", "enabled", c_.hydro);
  c_.gallery_per_state = f.integer("gallery", "per_state", c_.gallery_per_state);
  for (double v : c_.frequencies)
    if (!(v > 0)) f.fail("grid", "frequencies", "expected positive frequencies in Hz");
  for (double v : c_.gammas)
    if (!(v > 1)) f.fail("grid", "gammas", "expected Gamma > 1 (the layer must take off)");
  if (std::set<double>(c_.frequencies.begin(), c_.frequencies.end()).size() !=
      c_.frequencies.size())
    f.fail("grid", "frequencies", "expected distinct frequencies");
  if (std::set<double>(c_.gammas.begin(), c_.gammas.end()).size() != c_.gammas.size())
    f.fail("grid", "gammas", "expected distinct Gamma values");
  if (std::set<int>(c_.seeds.begin(), c_.seeds.end()).size() != c_.seeds.size())
    f.fail("particles", "seeds", "expected distinct seeds");
  if (!(c_.cycles >= 30)) f.fail("particles", "cycles", "expected at least 30 cycles");
  for (int law = 0; law < 2; ++law)
    for (double fr : c_.frequencies)
      for (double gamma : c_.gammas) {
        std::vector<std::string> o = c_.set;
        o.push_back(fmt::format("drive.frequency={}", g(fr)));
        o.push_back(fmt::format("drive.gamma={}", g(gamma)));
        o.push_back(fmt::format("run.duration={:.6g}", c_.cycles / fr));
        for (int seed : c_.seeds) {
          std::vector<std::string> os = o;
          os.push_back(fmt::format("run.seed={}", seed));
          RunRequest q = runRequest(RunKind::Particles, edLabel(law, fr, gamma, seed),
                                    studyScene(f, c_.path[law], os));
          q.window_cycles = c_.window;
          q.blocks = c_.blocks;
          requests_.push_back(std::move(q));
        }
        // The continuum has no seed; the scene names the first one only so that it is
        // complete (the seed does not enter the hydro solver).
        o.push_back(fmt::format("run.seed={}", c_.seeds.front()));
        if (c_.hydro)
          requests_.push_back(runRequest(RunKind::Hydro, hydroLabel(law, fr, gamma),
                                         studyScene(f, c_.path[law], o)));
      }
}

// "liquid-like (3/3), period 2 (2/3), psi6 0.63, bonds kept 0.07 over 15 cycles, 0.56 over
// one, surface wave 2/3 (mode 2, 1.7 d)"; the failed seeds and their first reason.
std::string describe(const LayerVerdict& v) {
  std::string s;
  if (v.failed > 0)
    s = fmt::format("{} of {} seeds failed: {}", v.failed, v.runs, shortReason(v.failure));
  if (v.period.of == 0) return s;
  if (!s.empty()) s += "; ";
  if (!v.classified())
    return s + fmt::format("period {} ({}/{}), not classified", v.period.value, v.period.count,
                           v.period.of);
  s += fmt::format(
      "{} ({}/{}), period {} ({}/{}), psi6 {:.2f}, bonds kept {:.2f} over 15 cycles, {:.2f} "
      "over one",
      v.state.value, v.state.count, v.state.of, v.period.value, v.period.count, v.period.of, v.psi6,
      v.bonds_kept, v.bonds_kept_per_cycle);
  const int waves =
      v.surface_wave.value ? v.surface_wave.count : v.surface_wave.of - v.surface_wave.count;
  if (waves > 0)
    s += fmt::format(", surface wave {}/{} (mode {}, {:.1f} d)", waves, v.surface_wave.of,
                     v.surface_wave_mode, v.surface_wave_amplitude_d);
  const int kinks = v.kinks.value ? v.kinks.count : v.kinks.of - v.kinks.count;
  if (kinks > 0) s += fmt::format(", kinks {}/{}", kinks, v.kinks.of);
  return s;
}

StabilityGrid StabilityStudy::verdicts(const RunSet& runs) const {
  StabilityGrid grid;
  grid.frequencies = c_.frequencies;
  grid.gammas = c_.gammas;
  for (int law = 0; law < 2; ++law)
    for (double fr : c_.frequencies)
      for (double gamma : c_.gammas) {
        std::vector<LayerPatterns> patterns;
        std::vector<bool> finished;
        std::vector<std::string> messages;
        for (int seed : c_.seeds) {
          const RunRecord& r = runs.get(edLabel(law, fr, gamma, seed));
          patterns.push_back(r.ok ? readLayerPatterns(r.fieldsPath()) : LayerPatterns{});
          finished.push_back(r.ok);
          messages.push_back(r.message);
        }
        grid.verdicts[law].push_back(voteOverSeeds(patterns, finished, messages));
      }
  return grid;
}

void StabilityStudy::diagrams(const StabilityGrid& grid, ReportSection& s) const {
  const std::size_t NF = c_.frequencies.size(), NG = c_.gammas.size();
  // Grid spacing, for the offset of the disagreement marker beside a point.
  auto spacing = [](const std::vector<double>& v) {
    return v.size() > 1
               ? (*std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end())) /
                     static_cast<double>(v.size() - 1)
               : 1.0;
  };
  const double dg = 0.3 * spacing(c_.gammas), df = 0.3 * spacing(c_.frequencies);
  for (int law = 0; law < 2; ++law) {
    Figure fig;
    fig.title = std::string("Stability diagram, ") + kLaw[law];
    fig.caption =
        "Particles, the most frequent verdict over the seeds. Unclassified or failed points are "
        "left blank; a grey star beside a point: its seeds disagree (state, period, waves or "
        "kinks), or some of them failed; the table gives the votes.";
    fig.xlabel = "Gamma";
    fig.ylabel = "f (Hz)";
    fig.legend_outside = true;
    for (std::size_t si = 0; si < kStates.size(); ++si) {
      std::vector<double> x, y;
      for (std::size_t i = 0; i < NF; ++i)
        for (std::size_t j = 0; j < NG; ++j) {
          const LayerVerdict& v = grid.at(law, i, j);
          if (v.classified() && v.state.value == kStates[si]) {
            x.push_back(c_.gammas[j]);
            y.push_back(c_.frequencies[i]);
          }
        }
      Series ss = lineSeries(x, y, kStates[si], kStateColor[si]);
      ss.style = "points";
      ss.marker = "s";
      fig.series.push_back(ss);
    }
    std::vector<double> wx, wy, kx, ky, px, py, ux, uy;
    for (std::size_t i = 0; i < NF; ++i)
      for (std::size_t j = 0; j < NG; ++j) {
        const LayerVerdict& v = grid.at(law, i, j);
        const double x = c_.gammas[j], y = c_.frequencies[i];
        if (v.classified() && v.surface_wave.value) wx.push_back(x), wy.push_back(y);
        if (v.classified() && v.kinks.value) kx.push_back(x), ky.push_back(y);
        if (v.period.of > 0 && v.period.value >= 2) px.push_back(x), py.push_back(y);
        if (v.classified() && !v.seedsAgree()) ux.push_back(x + dg), uy.push_back(y + df);
      }
    const struct {
      std::vector<double>&x, &y;
      const char *label, *color, *marker;
    } marks[] = {{wx, wy, "surface waves", "red", "^"},
                 {kx, ky, "kinks", "black", "x"},
                 {px, py, "period >= 2", "black", "."},
                 {ux, uy, "seeds disagree", "grey", "*"}};
    for (const auto& m : marks) {
      Series p = lineSeries(m.x, m.y, m.label, m.color);
      p.style = "points";
      p.marker = m.marker;
      fig.series.push_back(p);
    }
    s.add(std::move(fig));
  }

  // Differences dry - wet in the paper's symbols.
  Figure diff;
  diff.title = "Where dry and wet differ";
  diff.caption =
      "Points where the dry and the wet layer differ in a symbol of the paper's diagram (state, "
      "surface waves, kinks; most frequent over the seeds), and, separately, in the "
      "centre-of-mass period, which the paper's diagram does not show.";
  diff.xlabel = "Gamma";
  diff.ylabel = "f (Hz)";
  diff.legend_outside = true;
  std::vector<double> dx, dy, qx, qy;
  for (std::size_t i = 0; i < NF; ++i)
    for (std::size_t j = 0; j < NG; ++j) {
      if (grid.symbolsDiffer(i, j)) dx.push_back(c_.gammas[j]), dy.push_back(c_.frequencies[i]);
      if (grid.periodsDiffer(i, j)) qx.push_back(c_.gammas[j]), qy.push_back(c_.frequencies[i]);
    }
  Series ds = lineSeries(dx, dy, "state, waves or kinks differ", "purple");
  ds.style = "points";
  ds.marker = "D";
  Series qs = lineSeries(qx, qy, "period differs", "black");
  qs.style = "points";
  qs.marker = "+";
  diff.series.push_back(ds);
  diff.series.push_back(qs);
  s.add(std::move(diff));
}

void StabilityStudy::analyse(const RunSet& runs, h5::File& f, Report& report) const {
  f.createGroup(kRoot);
  const std::size_t NF = c_.frequencies.size(), NG = c_.gammas.size();
  const StabilityGrid grid = verdicts(runs);
  std::vector<std::string> hydro_cell[2];
  std::vector<double> hydro_period[2];
  for (int law = 0; law < 2; ++law)
    for (double fr : c_.frequencies)
      for (double gamma : c_.gammas) {
        std::string h = "not run";
        double hp = NAN;
        if (c_.hydro) {
          const RunRecord& rh = runs.get(hydroLabel(law, fr, gamma));
          if (rh.ok) {
            const HydroFields hf = readHydroFields(rh.hydroPath());
            hp = hf.periodic ? hf.period : 0;
            h = hf.periodic ? fmt::format("period {}", hf.period) : "no period";
          } else {
            h = "fails: " + shortReason(rh.message);
          }
        }
        hydro_cell[law].push_back(h);
        hydro_period[law].push_back(hp);
      }

  std::string seeds;
  for (int sd : c_.seeds) seeds += (seeds.empty() ? "" : ", ") + std::to_string(sd);
  ReportSection& s = report.section(
      "Stability diagrams",
      fmt::format(
          "Each (f, Gamma) point is {} particle run(s) of {:g} cycles (seeds {}), each classified "
          "live over its last 16 cycles at the free-flight phase (docs/classification.md): "
          "crystal / amorphous / liquid-like from the hexatic order and the bonds kept over 15 "
          "cycles, standing surface waves, kinks, and the centre-of-mass period. A point's label "
          "is the most frequent over its seeds (ties: the first seed listed). Markers: squares "
          "coloured by state; red triangles: surface waves; black crosses: kinks; a black dot: "
          "period 2 or more. A layer is caged (crystal or amorphous) when it keeps at least half "
          "of its neighbour bonds over the 15 cycles. This rule replaced a per-cycle mobility "
          "threshold after that threshold called the f = 10 Hz, Gamma = 2 layer liquid-like "
          "although it keeps 81 % of its bonds with <|psi6|> = 0.90 (the paper: solid there); "
          "the reasons, and what the old rule gave, are in docs/classification.md.",
          c_.seeds.size(), c_.cycles, seeds));
  diagrams(grid, s);

  const std::vector<double> diff_per_f = grid.symbolDifferencesPerFrequency();
  const std::vector<double> period_diff_per_f = grid.periodDifferencesPerFrequency();
  putSeries(f, kRoot + "/frequencies", c_.frequencies, "Hz");
  putSeries(f, kRoot + "/gammas", c_.gammas, "1");
  std::vector<double> seed_values(c_.seeds.begin(), c_.seeds.end());
  putSeries(f, kRoot + "/seeds", seed_values, "1");
  putSeries(f, kRoot + "/differences_per_frequency", diff_per_f, "1");
  putSeries(f, kRoot + "/period_differences_per_frequency", period_diff_per_f, "1");

  Table t;
  t.title = "Every point of the grid";
  t.caption =
      "Particles: the most frequent state and period over the seeds with their votes, the mean "
      "<|psi6|> and bonds kept (over the 15 cycles, which decides, and from one cycle to the "
      "next, reported) over the classified seeds, and how many seeds show surface waves "
      "or kinks. Hydro: one run per point (the continuum has no seed).";
  t.columns = {"f (Hz)", "Gamma", "dry (particles)", "wet (particles)", "hydro dry", "hydro wet"};
  for (std::size_t i = 0; i < NF; ++i)
    for (std::size_t j = 0; j < NG; ++j)
      t.rows.push_back({g(c_.frequencies[i]), g(c_.gammas[j]), describe(grid.at(0, i, j)),
                        describe(grid.at(1, i, j)), hydro_cell[0][i * NG + j],
                        hydro_cell[1][i * NG + j]});
  for (int law = 0; law < 2; ++law) {
    std::vector<double> state, state_votes, classified, period, period_votes, wave, wave_votes,
        kinks, kinks_votes, agree;
    for (const LayerVerdict& v : grid.verdicts[law]) {
      const auto it = std::find(kStates.begin(), kStates.end(), v.state.value);
      const bool c = v.classified();
      state.push_back(c && it != kStates.end() ? static_cast<double>(it - kStates.begin()) : NAN);
      state_votes.push_back(v.state.count);
      classified.push_back(v.state.of);
      period.push_back(v.period.of > 0 ? v.period.value : NAN);
      period_votes.push_back(v.period.count);
      wave.push_back(c ? v.surface_wave.value : NAN);
      wave_votes.push_back(v.surface_wave.count);
      kinks.push_back(c ? v.kinks.value : NAN);
      kinks_votes.push_back(v.kinks.count);
      agree.push_back(v.seedsAgree());
    }
    const std::string grp = fmt::format("{}/{}", kRoot, kLaw[law]);
    f.createGroup(grp);
    f.writeStringAttribute(grp, "state_codes", "0 crystal, 1 amorphous, 2 liquid-like");
    f.writeStringAttribute(grp, "layout",
                           "[frequency][gamma], row-major; most frequent over the seeds, "
                           "*_votes: seeds that gave it, classified_seeds: seeds that voted");
    putSeries(f, grp + "/state", state, "1");
    putSeries(f, grp + "/state_votes", state_votes, "1");
    putSeries(f, grp + "/classified_seeds", classified, "1");
    putSeries(f, grp + "/period", period, "1");
    putSeries(f, grp + "/period_votes", period_votes, "1");
    putSeries(f, grp + "/surface_wave", wave, "1");
    putSeries(f, grp + "/surface_wave_votes", wave_votes, "1");
    putSeries(f, grp + "/kinks", kinks, "1");
    putSeries(f, grp + "/kinks_votes", kinks_votes, "1");
    putSeries(f, grp + "/seeds_agree", agree, "1");
    putSeries(f, grp + "/hydro_period", hydro_period[law], "1");
  }

  ReportSection& q = report.section(
      "The paper's features, point by point",
      "Huang, Sec. III: at f = 10 Hz both layers fluidize as Gamma rises from 2 and solidify "
      "again at Gamma >= 6 (lid contact); for Gamma in [3, 5] the dry layer shows surface waves "
      "and the wet one does not; at Gamma ~ 5 both crystallize again as f rises; the dry-wet "
      "differences shrink as f rises. The first three are checked at the grid's lowest "
      "frequency. A difference is one in the paper's symbols (state, surface waves, kinks); "
      "the periods are compared separately.");
  reportPaperFeatures(grid, f, kRoot + "/features", q);
  s.add(std::move(t));
  gallery(runs, grid, report);

  std::string per_f, period_per_f;
  for (std::size_t i = 0; i < NF; ++i) {
    per_f += fmt::format("{}{:g} Hz: {:g}", i ? ", " : "", c_.frequencies[i], diff_per_f[i]);
    period_per_f +=
        fmt::format("{}{:g} Hz: {:g}", i ? ", " : "", c_.frequencies[i], period_diff_per_f[i]);
  }
  report.summary = fmt::format(
      "{} grid points per law (f = {:g} to {:g} Hz, Gamma = {:g} to {:g}), {} seed(s) each. "
      "Points where dry and wet differ in state, surface waves or kinks, per frequency: {}; in "
      "the period: {}.",
      NF * NG, c_.frequencies.front(), c_.frequencies.back(), c_.gammas.front(), c_.gammas.back(),
      c_.seeds.size(), per_f, period_per_f);
}

// The last recorded frame of a few runs per state: the first seed at each point whose run
// has the point's state.
void StabilityStudy::gallery(const RunSet& runs, const StabilityGrid& grid, Report& report) const {
  const std::size_t NF = c_.frequencies.size(), NG = c_.gammas.size();
  ReportSection& gal = report.section(
      "Snapshot gallery", "The last recorded frame (one per cycle, at phase 0) of up to " +
                              std::to_string(c_.gallery_per_state) +
                              " runs per state, so the classification can be checked by eye.");
  for (std::size_t si = 0; si < kStates.size(); ++si) {
    int shown = 0;
    for (int law = 0; law < 2 && shown < c_.gallery_per_state; ++law)
      for (std::size_t i = 0; i < NF && shown < c_.gallery_per_state; ++i)
        for (std::size_t j = 0; j < NG && shown < c_.gallery_per_state; ++j) {
          const LayerVerdict& v = grid.at(law, i, j);
          if (!(v.classified() && v.state.value == kStates[si])) continue;
          for (int seed : c_.seeds) {
            const RunRecord& r = runs.get(edLabel(law, c_.frequencies[i], c_.gammas[j], seed));
            if (!r.ok) continue;
            const LayerPatterns p = readLayerPatterns(r.fieldsPath());
            if (!(p.available && p.state == kStates[si])) continue;
            const Frame fr = readLastFrame(r.runPath());
            const double d = r.request.scene.particles.diameter;
            std::vector<double> x, z;
            for (std::size_t k = 0; k < fr.x.size(); ++k) {
              x.push_back(fr.x[k] / d);
              z.push_back(fr.z[k] / d);
            }
            Figure fg;
            fg.title = fmt::format("{}: {} f = {:g} Hz, Gamma = {:g}, seed {}", kStates[si],
                                   kLaw[law], c_.frequencies[i], c_.gammas[j], seed);
            fg.caption = fmt::format(
                "psi6 {:.2f}, bonds kept {:.2f} over 15 cycles, {:.2f} over one, period {}{}",
                p.psi6, p.bonds_kept, p.bonds_kept_per_cycle, p.period,
                p.surface_wave ? ", surface wave" : "");
            fg.xlabel = "x / d";
            fg.ylabel = "z / d";
            Series ps = lineSeries(x, z, "particles", kStateColor[si]);
            ps.style = "points";
            ps.marker = "o";
            fg.series.push_back(ps);
            const double w = r.request.scene.container.width / d;
            fg.series.push_back(lineSeries({0, w}, {fr.plate / d, fr.plate / d}, "plate", "black"));
            fg.legend = false;
            gal.add(std::move(fg));
            ++shown;
            break;
          }
        }
  }
}

}  // namespace

std::unique_ptr<Study> makeStabilityStudy(StudyFile& file) {
  return std::make_unique<StabilityStudy>(file);
}

}  // namespace granwave
