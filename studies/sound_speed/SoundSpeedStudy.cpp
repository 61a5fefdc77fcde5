#include "studies/sound_speed/SoundSpeedStudy.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "hydro/ShockRelations.hpp"
#include "hydro/SoundSpeed.hpp"
#include "scene/SceneDerived.hpp"
#include "studies/sound_speed/FrontStates.hpp"
#include "studies/framework/Measurement.hpp"
#include "studies/framework/StudyResults.hpp"
#include "studies/framework/StudyScenes.hpp"

namespace granwave {

namespace {

const char* kLaw[2] = {"dry", "wet"};
const std::string kRoot = "/results/sound_speed";
constexpr int kTheories = 6;
const char* kTheoryName[kTheories] = {"adiabatic sound speed c_s",
                                      "isothermal sound speed c_T",
                                      "Rankine-Hugoniot shock",
                                      "strong shock (cold gas ahead)",
                                      "compaction front (close packing behind)",
                                      "mass conservation (measured states)"};

std::string g(double v) { return fmt::format("{:g}", v); }

struct Config {
  std::string path[2];
  std::vector<std::string> set;
  double duration = 20;
  int seed = 1, window = 2, blocks = 5;
  std::vector<int> counts{150, 300, 600};
  std::vector<double> gammas{3, 4, 5};
  int rows = 3, gap = 1;
};

// The predictions of each theory for one set of states (front speeds relative to the gas
// ahead, m/s); NaN where a theory does not apply (no compression: U_p <= 0).
std::array<double, kTheories> predictions(const FrontStates& s, double mass,
                                          const hydro::RestitutionClosure& law) {
  std::array<double, kTheories> p;
  p.fill(NAN);
  const double theta = s.ahead.T / mass, nu = s.ahead.nu;
  if (!s.ahead.valid || !s.behind.valid || !(nu > 0 && nu < 1 && theta > 0)) return p;
  p[0] = hydro::adiabaticSoundSpeed(nu, theta, law);
  p[1] = hydro::isothermalSoundSpeed(nu, theta, law);
  const double up = s.behind.uz - s.ahead.uz;  // piston: the compacted layer behind
  if (up > 0) {
    p[2] = hydro::rankineHugoniot({nu, theta}, up, law).speed;
    p[3] = hydro::strongShock(nu, up, law).speed;
    if (nu < hydro::kHexagonalClosePacking) p[4] = hydro::compactionFrontSpeed(nu, up);
    if (s.behind.nu > nu) p[5] = up * s.behind.nu / (s.behind.nu - nu);
  }
  return p;
}

class SoundSpeedStudy final : public Study {
 public:
  explicit SoundSpeedStudy(StudyFile& f);
  std::string title() const override {
    return "Sound speed and shocks: does constant-restitution theory describe the fronts?";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  void analyse(const RunSet& runs, h5::File& f, Report& report) const override;

 private:
  std::string label(int law, int n, double gamma) const {
    return fmt::format("ED {} N={} Gamma={}", kLaw[law], n, g(gamma));
  }
  Config c_;
  Scene base_[2];
  std::vector<RunRequest> requests_;
};

SoundSpeedStudy::SoundSpeedStudy(StudyFile& f) {
  c_.path[0] = f.scenePath("scenes", "dry", "../scenes/paper-dry.toml");
  c_.path[1] = f.scenePath("scenes", "wet", "../scenes/paper-wet.toml");
  c_.set = f.strings("scenes", "set", {});
  c_.duration = f.number("particles", "duration", c_.duration);
  c_.seed = f.integer("particles", "seed", c_.seed);
  c_.window = f.integer("particles", "window_cycles", c_.window);
  c_.blocks = f.integer("particles", "blocks", c_.blocks);
  c_.counts = f.integers("particles", "counts", c_.counts);
  c_.gammas = f.numbers("particles", "gammas", c_.gammas);
  c_.rows = f.integer("states", "rows", c_.rows);
  c_.gap = f.integer("states", "gap", c_.gap);
  if (c_.rows < 1) f.fail("states", "rows", "expected at least 1 row");
  if (c_.gap < 1) f.fail("states", "gap", "expected at least 1 row between front and state");
  if (c_.blocks < 2) f.fail("particles", "blocks", "expected at least 2 blocks for the errors");
  for (int law = 0; law < 2; ++law) {
    base_[law] = studyScene(f, c_.path[law], c_.set);
    for (int n : c_.counts)
      for (double gamma : c_.gammas) {
        std::vector<std::string> o = c_.set;
        o.push_back(fmt::format("particles.count={}", n));
        o.push_back(fmt::format("drive.gamma={}", g(gamma)));
        o.push_back(fmt::format("run.seed={}", c_.seed));
        o.push_back(fmt::format("run.duration={}", g(c_.duration)));
        RunRequest q =
            runRequest(RunKind::Particles, label(law, n, gamma), studyScene(f, c_.path[law], o));
        q.window_cycles = c_.window;
        q.blocks = c_.blocks;
        requests_.push_back(std::move(q));
      }
  }
}

void SoundSpeedStudy::analyse(const RunSet& runs, h5::File& f, Report& report) const {
  f.createGroup(kRoot);
  ReportSection& s = report.section(
      "Fronts against sound-speed and shock theory",
      fmt::format(
          "Every impact front of the particle runs (dry and wet, N = {}, Gamma = {}; {:g} s, "
          "seed {}). The gas ahead is the {} rows (diameters) starting {} row(s) above the "
          "front, the gas behind the same below it, area-fraction weighted and averaged over "
          "the front's phases. The front speed w is taken relative to the gas ahead; the "
          "piston speed U_p is the velocity of the gas behind relative to the gas ahead. "
          "Theories (hydro/SoundSpeed.hpp, hydro/ShockRelations.hpp), each evaluated with the "
          "Maxwell-averaged closure of the layer's own law at the temperature ahead: the "
          "adiabatic and isothermal sound speeds; the Rankine-Hugoniot shock driven by U_p; "
          "the strong shock into cold gas; the compaction front (close packing behind); and "
          "mass conservation across the measured states. A theory holds for a front when it "
          "lies within 2 combined sigma of w (errors: the front's fit and block errors, and "
          "the spread of each prediction over the blocks).",
          "[" +
              [&] {
                std::string x;
                for (int n : c_.counts) x += (x.empty() ? "" : ", ") + std::to_string(n);
                return x;
              }() +
              "]",
          "[" +
              [&] {
                std::string x;
                for (double v : c_.gammas) x += (x.empty() ? "" : ", ") + g(v);
                return x;
              }() +
              "]",
          c_.duration, c_.seed, c_.rows, c_.gap));
  Table states;
  states.title = "States ahead of and behind each front";
  states.columns = {"run",       "front at t/T",     "nu ahead",  "T ahead / T0", "u_z ahead (m/s)",
                    "nu behind", "u_z behind (m/s)", "U_p (m/s)", "w (m/s)"};
  Table cmp;
  cmp.title = "Front speed against each theory (relative to the gas ahead, m/s)";
  cmp.caption =
      "Each cell: prediction ± spread over blocks, then (w - prediction) / prediction "
      "and whether it holds (2 sigma).";
  cmp.columns = {"run", "w (m/s)", "Mach w/c_s"};
  for (const char* t : kTheoryName) cmp.columns.push_back(t);
  std::array<int, kTheories> holds{}, tested{};
  Figure fig;
  fig.title = "Measured front speed against each theory";
  fig.caption = "Each point is one front; on the dashed line theory and particles agree.";
  fig.xlabel = "predicted speed relative to the gas ahead (m/s)";
  fig.ylabel = "measured w (m/s)";
  std::array<std::vector<double>, kTheories> px, py, pxe, pye;
  std::vector<double> all_w, all_mach;
  for (int law = 0; law < 2; ++law) {
    const hydro::RestitutionClosure closure = restitutionClosure(base_[law]);
    const double mass = derive(base_[law]).mass;
    for (int n : c_.counts)
      for (double gamma : c_.gammas) {
        const std::string name = label(law, n, gamma);
        const RunRecord& r = runs.get(name);
        if (!r.ok) {
          states.rows.push_back({name, "failed: " + r.message, "–", "–", "–", "–", "–", "–", "–"});
          continue;
        }
        const ParticleFields p = readParticleFields(r.fieldsPath());
        for (const Front& fr : p.fronts) {
          if (!fr.from_impact || !std::isfinite(fr.speed)) continue;
          const std::vector<int> phases = episodePhases(p, fr.first_phase);
          const FrontStates st = frontStates(p, phases, c_.rows, c_.gap);
          if (!st.ahead.valid || !st.behind.valid) {
            states.rows.push_back({name, formatNumber(fr.start), "–", "–", "–", "–", "–", "–",
                                   "no state: the front reaches the edge of the layer (failed to "
                                   "sample)"});
            continue;
          }
          std::vector<std::array<double, kTheories>> per_block;
          std::vector<double> ua_block;
          for (int b = 0; b < p.blocks; ++b) {
            const FrontStates sb = frontStates(p, phases, c_.rows, c_.gap, b);
            per_block.push_back(predictions(sb, mass, closure));
            ua_block.push_back(sb.ahead.valid ? sb.ahead.uz : NAN);
          }
          auto spread = [](const std::vector<double>& v) { return meanAndStandardError(v).error; };
          const double ua_err = spread(ua_block);
          const Measurement w{fr.speed - st.ahead.uz,
                              std::hypot(fr.error, std::isfinite(ua_err) ? ua_err : 0.0)};
          const auto pred = predictions(st, mass, closure);
          const std::string case_name = fmt::format("{} (t/T {:.2f})", name, fr.start);
          states.rows.push_back({name, formatNumber(fr.start), formatNumber(st.ahead.nu, 3),
                                 formatNumber(st.ahead.T / p.T0, 3), formatNumber(st.ahead.uz),
                                 formatNumber(st.behind.nu, 3), formatNumber(st.behind.uz),
                                 formatNumber(st.behind.uz - st.ahead.uz), format(w)});
          std::vector<std::string> row{case_name, format(w), formatNumber(w.value / pred[0], 2)};
          all_w.push_back(w.value);
          all_mach.push_back(w.value / pred[0]);
          for (int k = 0; k < kTheories; ++k) {
            std::vector<double> vb;
            for (const auto& b : per_block) vb.push_back(b[static_cast<std::size_t>(k)]);
            const Measurement m{pred[k], spread(vb)};
            if (!m.valid()) {
              row.push_back("n/a (no compression)");
              continue;
            }
            const double z = sigmaDistance(w, m);
            const bool ok = std::isfinite(z) && std::abs(z) <= 2;
            ++tested[k];
            if (ok) ++holds[k];
            row.push_back(fmt::format("{}: {:+.0f} %, {}", format(m),
                                      100 * (w.value - m.value) / m.value,
                                      ok ? "holds" : "misses"));
            px[k].push_back(m.value);
            pxe[k].push_back(std::isfinite(m.error) ? m.error : 0.0);
            py[k].push_back(w.value);
            pye[k].push_back(w.error);
          }
          cmp.rows.push_back(row);
        }
      }
  }
  const char* colors[kTheories] = {"tab:blue",   "tab:cyan",  "tab:red",
                                   "tab:orange", "tab:green", "tab:purple"};
  double top = 0;
  for (int k = 0; k < kTheories; ++k) {
    if (px[k].empty()) continue;
    Series sk = errorSeries(px[k], py[k], pye[k], kTheoryName[k], colors[k]);
    sk.xerr = pxe[k];
    sk.linestyle = "none";
    fig.series.push_back(sk);
    for (double v : px[k]) top = std::max(top, v);
    for (double v : py[k]) top = std::max(top, v);
    const std::string grp = fmt::format("{}/theory_{}", kRoot, k);
    f.createGroup(grp);
    f.writeStringAttribute(grp, "name", kTheoryName[k]);
    putSeries(f, grp + "/predicted", px[k], "m s-1");
    putSeries(f, grp + "/predicted_error", pxe[k], "m s-1");
    putSeries(f, grp + "/measured", py[k], "m s-1");
    putSeries(f, grp + "/measured_error", pye[k], "m s-1");
    putValue(f, grp, "fronts_tested", tested[k]);
    putValue(f, grp, "fronts_where_it_holds", holds[k]);
  }
  Series diag = lineSeries({0.0, top * 1.1}, {0.0, top * 1.1}, "agreement", "black");
  diag.linestyle = "--";
  fig.series.push_back(diag);
  putSeries(f, kRoot + "/front_speed_relative", all_w, "m s-1");
  putSeries(f, kRoot + "/mach_number", all_mach, "1");

  Table verdict;
  verdict.title = "How often each theory holds";
  verdict.columns = {"theory", "fronts tested", "holds within 2 sigma"};
  std::string summary;
  for (int k = 0; k < kTheories; ++k) {
    verdict.rows.push_back({kTheoryName[k], std::to_string(tested[k]), std::to_string(holds[k])});
    summary += fmt::format("{}: holds for {} of {} fronts. ", kTheoryName[k], holds[k], tested[k]);
  }
  s.add(std::move(verdict));
  s.add(std::move(fig));
  s.add(std::move(cmp));
  s.add(std::move(states));
  report.summary = summary;
}

}  // namespace

std::unique_ptr<Study> makeSoundSpeedStudy(StudyFile& file) {
  return std::make_unique<SoundSpeedStudy>(file);
}

}  // namespace granwave
