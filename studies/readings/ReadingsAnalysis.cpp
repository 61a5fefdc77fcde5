#include "studies/readings/ReadingsAnalysis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "coarse_grain/FieldsReader.hpp"
#include "studies/contract/FailureReason.hpp"
#include "studies/contract/StudyResults.hpp"
#include "studies/run_files/RunOutputs.hpp"
#include "studies/wave_analysis/ImpactFronts.hpp"  // centerOfMassMinimumPhases
#include "studies/wave_analysis/VelocityFronts.hpp"
#include "studies/wave_analysis/WaveMomentumRatio.hpp"

namespace granwave {

// The paper's statements (Huang, Secs. III-V), each with the number the check compares.
const StatementText kStatementTexts[kStatements] = {
    {"dry CM period 2T at 10 Hz, Gamma 4"},
    {"wet CM period 2T at 10 Hz, Gamma 4"},
    {"dry CM minimum at t/T = 0.92"},
    {"wet CM minimum at t/T = 0.90"},
    {"dry surface waves at Gamma 3-5 (10 Hz)"},
    {"no wet surface waves at Gamma 3-5 (10 Hz)"},
    {"crystal again at Gamma ~ 5 as f rises (dry and wet)"},
    {"wet weak-impact front 1.61 +- 0.25 m/s"},
    {"wet strong-impact front 1.95 +- 0.25 m/s"},
    {"r_x = 2.17 +- 0.56 over the wave"},
};

SeedFraction seedFraction(int count, int of) {
  SeedFraction f{count, of, 0, 1};
  if (of <= 0) return f;
  // Wilson score interval at z = 1 (68 %): honest at 0/n and n/n, unlike p +- sqrt(p(1-p)/n).
  const double n = of, p = count / n, z2 = 1.0;
  const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
  const double half = std::sqrt(p * (1 - p) / n + z2 / (4 * n * n)) / (1 + z2 / n);
  f.low = centre - half;
  f.high = centre + half;
  return f;
}

const char* verdictName(Verdict v) {
  switch (v) {
    case Verdict::Holds:
      return "holds";
    case Verdict::Fails:
      return "fails";
    case Verdict::Undecided:
      return "undecided";
    case Verdict::NoData:
      return "no data";
  }
  return "no data";
}

Verdict majority(const SeedFraction& f) {
  if (f.of == 0) return Verdict::NoData;
  if (f.low > 0.5) return Verdict::Holds;
  if (f.high < 0.5) return Verdict::Fails;
  return Verdict::Undecided;
}

Verdict agrees(const Measurement& m, double paper, double tolerance) {
  if (!std::isfinite(m.value)) return Verdict::NoData;
  const double err = std::isfinite(m.error) ? m.error : 0.0;
  if (std::abs(m.value - paper) > 2 * std::hypot(err, tolerance)) return Verdict::Fails;
  return err > tolerance ? Verdict::Undecided : Verdict::Holds;
}

int ReadingOutcome::holds() const {
  int n = 0;
  for (Verdict v : verdict) n += v == Verdict::Holds;
  return n;
}

namespace {

constexpr double kPhaseRounding = 0.005;  // the paper's phases are given to two decimals

// Circular mean of phases in [0, 1).
double meanPhase(const std::vector<double>& phases) {
  double c = 0, s = 0;
  for (double x : phases) {
    c += std::cos(2 * std::numbers::pi * x);
    s += std::sin(2 * std::numbers::pi * x);
  }
  const double m = std::atan2(s, c) / (2 * std::numbers::pi);
  return m < 0 ? m + 1 : m;
}

// Mean and standard error of per-seed phases, unwrapped around their circular mean.
Measurement phaseOverSeeds(const std::vector<double>& phases) {
  if (phases.empty()) return {};
  const double centre = meanPhase(phases);
  std::vector<double> unwrapped;
  for (double x : phases) unwrapped.push_back(centre + std::remainder(x - centre, 1.0));
  Measurement m = meanAndStandardError(unwrapped);
  m.value -= std::floor(m.value);
  return m;
}

// What one law's runs at one drive point give, seed by seed.
struct PointRuns {
  std::vector<LayerPatterns> patterns;
  std::vector<std::optional<FieldsRecord>> fields;  // wave point only
  std::vector<RunObservables> observables;          // wave point only
};

PointRuns readPoint(const ReadingsConfig& c, const RunSet& runs, int r, int law,
                    const DrivePoint& p, bool wave, ReadingOutcome& o) {
  PointRuns out;
  for (int seed : c.seeds) {
    const RunRecord& rec = runs.get(c.run(r, law, p, seed));
    o.cpu_seconds += rec.cpu;
    if (!rec.ok) {
      ++o.failed_runs;
      if (o.first_failure.empty()) o.first_failure = shortReason(rec.message);
      if (wave) out.fields.emplace_back();
      continue;
    }
    out.patterns.push_back(readLayerPatterns(rec.fieldsPath()));
    if (!wave) continue;
    out.fields.push_back(readFieldsFile(rec.fieldsPath()));
    out.observables.push_back(readRunObservables(rec.runPath()));
  }
  return out;
}

template <class Predicate>
SeedFraction countRuns(const std::vector<LayerPatterns>& runs, Predicate yes) {
  int k = 0, n = 0;
  for (const LayerPatterns& l : runs) {
    if (!l.available) continue;
    ++n;
    k += yes(l) ? 1 : 0;
  }
  return seedFraction(k, n);
}

// Period, CM minimum, TC share of one law at the wave point.
void waveLaw(const PointRuns& w, int law, ReadingOutcome& o) {
  o.period2[law] = countRuns(w.patterns, [](const LayerPatterns& l) { return l.period == 2; });
  std::vector<double> phases;
  for (const auto& f : w.fields) {
    if (!f) continue;
    phases.push_back(meanPhase(centerOfMassMinimumPhases(f->profiles, f->cycles_per_window)));
    const int per_cycle =
        f->cycles_per_window > 0 ? f->profiles.phases() / f->cycles_per_window : 0;
    if (per_cycle > 0) o.phase_resolution = 1.0 / per_cycle;
  }
  o.minimum_phase[law] = phaseOverSeeds(phases);
  double elastic = 0, all = 0;
  for (const RunObservables& r : w.observables) {
    elastic += static_cast<double>(r.tc_elastic);
    all += static_cast<double>(r.pair_collisions + r.wall_collisions);
  }
  o.tc_elastic_share[law] = all > 0 ? elastic / all : std::numeric_limits<double>::quiet_NaN();
}

// Fronts of the wet layer and r_x of each seed with both layers. The fronts are tracked by the
// velocity jump: on this scene the T~g peak jumps from near the plate to the top of the layer
// within one phase, so a line through its heights is no front speed (docs/studies.md, "Front
// speeds on the paper's scene"); weak and strong are told apart by the peak T~g/T0 of the T~g-peak
// fronts.
void waveFrontsAndRatio(const ReadingsConfig& c, const PointRuns (&w)[kLaws], ReadingOutcome& o) {
  std::vector<VelocityFronts> fronts;
  std::vector<double> ratios;
  const WaveRatioOptions opt{c.wave_duration, 0.88, c.min_rms, c.min_area_fraction};
  for (std::size_t s = 0; s < w[1].fields.size(); ++s) {
    const auto& wet = w[1].fields[s];
    if (!wet) continue;
    fronts.push_back(velocityFronts(*wet));
    const auto& dry = s < w[0].fields.size() ? w[0].fields[s] : std::nullopt;
    if (!dry) continue;
    const Measurement r = waveMomentumRatio(*dry, *wet, opt);
    if (std::isfinite(r.value)) ratios.push_back(r.value);
  }
  if (!fronts.empty()) {
    const VelocityFronts all = combineVelocityFronts(fronts);
    o.weak_front = all.weak;
    o.strong_front = all.strong;
  }
  if (!ratios.empty()) o.momentum_ratio = meanAndStandardError(ratios);
}

std::string fractionText(const SeedFraction& f) {
  return f.of == 0 ? "no runs" : fmt::format("{}/{}", f.count, f.of);
}

// All of several majority verdicts: holds if all hold, fails if any fails.
Verdict allOf(const std::vector<Verdict>& v) {
  bool any_undecided = false;
  for (Verdict x : v) {
    if (x == Verdict::Fails) return Verdict::Fails;
    if (x == Verdict::NoData) return Verdict::NoData;
    any_undecided = any_undecided || x == Verdict::Undecided;
  }
  return any_undecided ? Verdict::Undecided : Verdict::Holds;
}

SeedFraction complement(const SeedFraction& f) { return seedFraction(f.of - f.count, f.of); }

void judgeWaves(ReadingOutcome& o) {
  std::vector<Verdict> dry, wet;
  std::string dry_text, wet_text;
  for (std::size_t g = 0; g < o.waves[0].size(); ++g) {
    dry.push_back(majority(o.waves[0][g]));
    wet.push_back(majority(complement(o.waves[1][g])));
    const char* sep = g ? ", " : "";
    dry_text += fmt::format("{}{}", sep, fractionText(o.waves[0][g]));
    wet_text += fmt::format("{}{}", sep, fractionText(o.waves[1][g]));
  }
  o.verdict[kDryWaves] = allOf(dry);
  o.verdict[kNoWetWaves] = allOf(wet);
  o.measured[kDryWaves] = "waves in " + dry_text;
  o.measured[kNoWetWaves] = "waves in " + wet_text;
}

// Crystals at Gamma ~ 5 as f rises: judged at the highest frequency, every one listed.
void judgeCrystals(const ReadingsConfig& c, ReadingOutcome& o) {
  o.verdict[kCrystalAtHighF] =
      allOf({majority(o.crystal_high[0].back()), majority(o.crystal_high[1].back())});
  std::string text = "crystal";
  for (std::size_t i = 0; i < c.high_frequencies.size(); ++i)
    text +=
        fmt::format("{} {} Hz: dry {}, wet {}", i ? ";" : "", formatCompact(c.high_frequencies[i]),
                    fractionText(o.crystal_high[0][i]), fractionText(o.crystal_high[1][i]));
  o.measured[kCrystalAtHighF] = text;
}

void judge(const ReadingsConfig& c, ReadingOutcome& o) {
  for (int law = 0; law < kLaws; ++law) {
    o.verdict[kDryPeriod2 + law] = majority(o.period2[law]);
    o.measured[kDryPeriod2 + law] = fractionText(o.period2[law]) + " seeds period 2";
  }
  const double tol = std::hypot(kPhaseRounding, o.phase_resolution / std::sqrt(12.0));
  o.verdict[kDryMinimumPhase] = agrees(o.minimum_phase[0], 0.92, tol);
  o.verdict[kWetMinimumPhase] = agrees(o.minimum_phase[1], 0.90, tol);
  o.measured[kDryMinimumPhase] = format(o.minimum_phase[0], 2);
  o.measured[kWetMinimumPhase] = format(o.minimum_phase[1], 2);
  judgeWaves(o);
  judgeCrystals(c, o);
  o.verdict[kWeakFront] = agrees(o.weak_front, 1.61, 0.25);
  o.verdict[kStrongFront] = agrees(o.strong_front, 1.95, 0.25);
  o.verdict[kMomentumRatio] = agrees(o.momentum_ratio, 2.17, 0.56);
  o.measured[kWeakFront] = format(o.weak_front, 2, "m/s");
  o.measured[kStrongFront] = format(o.strong_front, 2, "m/s");
  o.measured[kMomentumRatio] = format(o.momentum_ratio, 2);
}

ReadingOutcome analyseReading(const ReadingsConfig& c, const RunSet& runs, int r) {
  ReadingOutcome o;
  const std::vector<DrivePoint> points = c.points();
  const int wave = c.wavePoint();
  PointRuns at_wave[kLaws];
  for (int law = 0; law < kLaws; ++law)
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
      PointRuns p = readPoint(c, runs, r, law, points[i], i == wave, o);
      if (i >= static_cast<int>(c.gammas.size())) {
        o.crystal_high[law].push_back(
            countRuns(p.patterns, [](const LayerPatterns& l) { return l.state == "crystal"; }));
        continue;
      }
      o.waves[law].push_back(
          countRuns(p.patterns, [](const LayerPatterns& l) { return l.surface_wave; }));
      if (i == wave) at_wave[law] = std::move(p);
    }
  for (int law = 0; law < kLaws; ++law) waveLaw(at_wave[law], law, o);
  waveFrontsAndRatio(c, at_wave, o);
  const double kappa = c.readings[r].kappa_si;
  o.e_dry_1ms = 1 - kappa;
  o.e_dry_v0 = 1 - kappa * std::pow(c.wave_v0, 0.2);
  judge(c, o);
  return o;
}

}  // namespace

ReadingsResults analyseReadings(const ReadingsConfig& c, const RunSet& runs) {
  ReadingsResults r;
  for (int i = 0; i < static_cast<int>(c.readings.size()); ++i)
    r.readings.push_back(analyseReading(c, runs, i));
  return r;
}

void writeReadingsResults(h5::File& f, const ReadingsConfig& c, const ReadingsResults& r) {
  const std::string root = "/results/readings";
  std::vector<double> verdicts, holds;
  for (const ReadingOutcome& o : r.readings) {
    for (Verdict v : o.verdict) verdicts.push_back(static_cast<double>(v));
    holds.push_back(o.holds());
  }
  putSeries(f, root + "/statements_held", holds, "count");
  f.writeDataset(root + "/verdicts", verdicts, {r.readings.size(), std::size_t{kStatements}});
  f.writeStringAttribute(root + "/verdicts", "codes", "0 holds, 1 fails, 2 undecided, 3 no data");
  f.writeStringAttribute(root + "/verdicts", "unit", "1");
  for (std::size_t i = 0; i < r.readings.size(); ++i) {
    const ReadingOutcome& o = r.readings[i];
    const std::string g = fmt::format("{}/reading_{}", root, i);
    putValue(f, g, "kappa_si", c.readings[i].kappa_si);
    putValue(f, g, "e_dry_1ms", o.e_dry_1ms);
    putValue(f, g, "e_dry_v0", o.e_dry_v0);
    f.writeStringAttribute(g, "name", c.readings[i].name);
    for (int law = 0; law < kLaws; ++law) {
      const std::string l = kLawNames[law];
      putValue(f, g, "period2_fraction_" + l, o.period2[law].fraction());
      putMeasurement(f, g, "minimum_phase_" + l, o.minimum_phase[law]);
      std::vector<double> crystals;
      for (const SeedFraction& x : o.crystal_high[law]) crystals.push_back(x.fraction());
      putSeries(f, g + "/crystal_fraction_" + l, crystals, "fraction of seeds");
      putValue(f, g, "tc_elastic_share_" + l, o.tc_elastic_share[law]);
      std::vector<double> waves;
      for (const SeedFraction& w : o.waves[law]) waves.push_back(w.fraction());
      putSeries(f, g + "/wave_fraction_" + l, waves, "fraction of seeds");
    }
    putMeasurement(f, g, "weak_front", o.weak_front);
    putMeasurement(f, g, "strong_front", o.strong_front);
    putMeasurement(f, g, "momentum_ratio", o.momentum_ratio);
    putValue(f, g, "cpu_seconds", o.cpu_seconds);
    putValue(f, g, "failed_runs", o.failed_runs);
  }
}

}  // namespace granwave
