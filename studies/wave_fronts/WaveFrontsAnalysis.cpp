#include "studies/wave_fronts/WaveFrontsAnalysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "studies/contract/StudyResults.hpp"

namespace granwave {

namespace {

const std::string kRoot = "/results/wave_fronts";

PaperLaw paperLaw(const WaveFrontsConfig& c, const RunSet& runs, int law) {
  PaperLaw out;
  std::vector<ImpactFronts> per_seed;
  std::vector<VelocityFronts> tracked;
  std::vector<double> minima;
  for (int seed : c.seeds) {
    auto p = particleFields(runs, WaveFrontsConfig::particleRun(law, fmt::format("seed {}", seed)));
    if (!p) continue;
    per_seed.push_back(impactFronts(p->profiles));
    tracked.push_back(velocityFronts(*p));
    const double jump = PaperLaw::kPeakJumpSpeed * p->cycles_per_window /
                        (p->context.frequency * p->profiles.phases());
    for (const FrontEpisode& f : p->profiles.fronts) {
      if (!f.from_impact) continue;
      ++out.peak_fronts;
      out.peak_jumps += peakJumps(p->profiles, f, jump);
    }
    for (double m : centerOfMassMinimumPhases(p->profiles, p->cycles_per_window))
      minima.push_back(m);
    out.periods.push_back(p->context.layer_period);
    if (seed == c.seeds.front()) out.seed1 = p;
    if (!out.first) out.first = std::move(p);
  }
  out.ed = combineImpactFronts(per_seed);
  out.tracked = combineVelocityFronts(tracked);
  out.seeds_used = static_cast<int>(per_seed.size());
  out.collision_phase = meanPhase(minima);
  out.hydro[0] = hydroOutcome(runs, WaveFrontsConfig::hydroRun(law, "velocity"));
  out.hydro[1] = hydroOutcome(runs, WaveFrontsConfig::hydroRun(law, "constant"));
  for (HydroOutcome& h : out.hydro)
    h.tracked = trackedHydroFronts(h, c.scenes.base[law].drive.frequency).speed;
  return out;
}

// Particles (seed 1) and hydro at one sweep point.
SweepPoint sweepPoint(const RunSet& runs, const std::string& particle_label,
                      const std::string& hydro_label, double particle_cycles) {
  SweepPoint s;
  if (auto p = particleFields(runs, particle_label)) {
    s.ed_cpu_per_cycle = runs.get(particle_label).cpu / particle_cycles;
    s.ed = impactFronts(p->profiles).all;
    s.collision_phase = meanPhase(centerOfMassMinimumPhases(p->profiles, p->cycles_per_window));
    s.layer_period = p->context.layer_period;
  }
  const HydroOutcome h = hydroOutcome(runs, hydro_label);
  s.hydro_ok = h.fields.has_value();
  s.hydro_failure = h.failure;
  if (s.hydro_ok) {
    s.hydro = h.fronts.all;
    s.hydro_cpu = h.cpu;  // as recorded, as the particles' run: the whole process
    s.hydro_period = h.fields->periodic ? static_cast<int>(h.fields->period) : 0;
  }
  return s;
}

// The N sweep's point `n`: the velocity-jump tracker on every seed's run and on the hydro run
// (its time between phases from the window's t/T and the scene's frequency).
void trackSweepPoint(const WaveFrontsConfig& c, const RunSet& runs, int law, int n, SweepPoint& s) {
  std::vector<VelocityFronts> seeds, period2;
  for (int sd : c.sweep_seeds) {
    const std::string label = WaveFrontsConfig::particleRun(
        law, WaveFrontsConfig::countTag(n, sd, c.sweep_seeds.front()));
    const auto p = particleFields(runs, label);
    if (!p) continue;
    seeds.push_back(velocityFronts(*p));
    s.seed_periods.push_back(p->context.layer_period);
    if (const auto state = readStateFields(runs.get(label).fieldsPath(), 2))
      period2.push_back(velocityFronts(*state));
  }
  s.tracked_seeds = static_cast<int>(seeds.size());
  s.tracked = combineVelocityFronts(seeds);
  s.period2_seeds = static_cast<int>(period2.size());
  if (!period2.empty()) s.tracked_period2 = combineVelocityFronts(period2);
  const HydroOutcome h =
      hydroOutcome(runs, WaveFrontsConfig::hydroRun(law, fmt::format("N={}", n)));
  s.hydro_tracked = trackedHydroFronts(h, c.scenes.base[law].drive.frequency);
}

ParameterSweep wetSweep(const WaveFrontsConfig& c, const RunSet& runs, const std::string& key,
                        const std::vector<double>& values) {
  ParameterSweep sw{key, values, {}};
  for (double v : values) {
    const std::string tag = fmt::format("{}={}", key, formatCompact(v));
    sw.points.push_back(sweepPoint(runs, WaveFrontsConfig::particleRun(1, tag),
                                   WaveFrontsConfig::hydroRun(1, tag), c.sweepCycles(1)));
  }
  return sw;
}

void writePaper(h5::File& f, int law, const PaperLaw& p) {
  const std::string name = kLawNames[law];
  const std::string g_ed = fmt::format("{}/ed_{}", kRoot, name);
  putMeasurement(f, g_ed, "weak", p.ed.weak);
  putMeasurement(f, g_ed, "strong", p.ed.strong);
  putMeasurement(f, g_ed, "all", p.ed.all);
  putValue(f, g_ed, "collision_phase", p.collision_phase);
  // The velocity-jump front (all impacts, weak, strong) and the T~g-peak fronts that jump.
  putMeasurement(f, g_ed, "velocity_jump", p.tracked.speed);
  putMeasurement(f, g_ed, "velocity_jump_weak", p.tracked.weak);
  putMeasurement(f, g_ed, "velocity_jump_strong", p.tracked.strong);
  putValue(f, g_ed, "peak_fronts", p.peak_fronts);
  putValue(f, g_ed, "peak_fronts_jumping", p.peak_jumps);
  const char* variants[2] = {"velocity", "constant"};
  for (int v = 0; v < 2; ++v) {
    const HydroOutcome& h = p.hydro[v];
    if (!h.fields) continue;
    const std::string gh = fmt::format("{}/hydro_{}_{}", kRoot, name, variants[v]);
    putMeasurement(f, gh, "weak", h.fronts.weak);
    putMeasurement(f, gh, "strong", h.fronts.strong);
    putMeasurement(f, gh, "all", h.fronts.all);
    putMeasurement(f, gh, "velocity_jump", h.tracked);
    putValue(f, gh, "period", h.fields->period);
    putValue(f, gh, "collision_phase", h.collision_phase);
  }
}

// The fronts' transits through the layer's mass, particles (pooled, and their period-2 windows)
// and hydro: `transit_dense` (mass fractions 0.1-0.5) and `transit_upper` (0.5-0.9), each with
// `_error`, `_lower_bound` and the counts `_fronts`, `_reached`, `_resolved`.
void writeTransits(h5::File& f, const std::string& grp, const std::vector<SweepPoint>& points) {
  const char* names[2] = {"transit_dense", "transit_upper"};
  const char* sources[3] = {"tracked", "hydro_tracked", "tracked_period2"};
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 3; ++k) {
      std::vector<double> v, e, b, fronts, reached, resolved;
      for (const SweepPoint& p : points) {
        const VelocityFronts& from =
            k == 0 ? p.tracked : (k == 1 ? p.hydro_tracked : p.tracked_period2);
        const TransitSpeeds& t = from.transit[i];
        v.push_back(t.speed.value);
        e.push_back(t.speed.error);
        b.push_back(t.lower_bound);
        fronts.push_back(t.fronts);
        reached.push_back(t.reached);
        resolved.push_back(t.resolved);
      }
      const std::string base = fmt::format("{}/{}_{}", grp, sources[k], names[i]);
      putSeries(f, base, v, "m s-1");
      putSeries(f, base + "_error", e, "m s-1");
      putSeries(f, base + "_lower_bound", b, "m s-1");
      // Fronts counted (over seeds), those passing both fractions, those with a speed.
      putSeries(f, base + "_fronts", fronts, "1");
      putSeries(f, base + "_reached", reached, "1");
      putSeries(f, base + "_resolved", resolved, "1");
    }
}

// The velocity-jump tracker's N sweep: speeds with errors, Rankine-Hugoniot speeds, lower
// bounds of fronts faster than the sampling, seeds used.
void writeTracked(h5::File& f, const std::string& grp, const std::vector<SweepPoint>& points) {
  std::vector<double> v, e, j, je, bound, seeds, hv, he, hj, hje;
  for (const SweepPoint& p : points) {
    v.push_back(p.tracked.speed.value);
    e.push_back(p.tracked.speed.error);
    j.push_back(p.tracked.jump_speed.value);
    je.push_back(p.tracked.jump_speed.error);
    bound.push_back(p.tracked.lower_bound);
    seeds.push_back(p.tracked_seeds);
    hv.push_back(p.hydro_tracked.speed.value);
    he.push_back(p.hydro_tracked.speed.error);
    hj.push_back(p.hydro_tracked.jump_speed.value);
    hje.push_back(p.hydro_tracked.jump_speed.error);
  }
  putSeries(f, grp + "/tracked_speed", v, "m s-1");
  putSeries(f, grp + "/tracked_speed_error", e, "m s-1");
  putSeries(f, grp + "/tracked_jump_speed", j, "m s-1");
  putSeries(f, grp + "/tracked_jump_speed_error", je, "m s-1");
  putSeries(f, grp + "/tracked_lower_bound", bound, "m s-1");
  putSeries(f, grp + "/tracked_seeds", seeds, "1");
  putSeries(f, grp + "/hydro_tracked_speed", hv, "m s-1");
  putSeries(f, grp + "/hydro_tracked_speed_error", he, "m s-1");
  putSeries(f, grp + "/hydro_tracked_jump_speed", hj, "m s-1");
  putSeries(f, grp + "/hydro_tracked_jump_speed_error", hje, "m s-1");
  writeTransits(f, grp, points);
}

void writeSweeps(h5::File& f, const WaveFrontsConfig& c, const WaveFrontsResults& r) {
  for (int law = 0; law < kLaws; ++law) {
    std::vector<double> x, y, e, cmin, yh;
    for (std::size_t i = 0; i < c.counts.size(); ++i) {
      const SweepPoint& s = r.n_sweep[law][i];
      x.push_back(c.counts[i]);
      y.push_back(s.ed.value);
      e.push_back(s.ed.error);
      cmin.push_back(s.collision_phase);
      yh.push_back(s.hydro.value);
    }
    const std::string grp = fmt::format("{}/n_sweep/{}", kRoot, kLawNames[law]);
    f.createGroup(grp);
    putSeries(f, grp + "/count", x, "1");
    putSeries(f, grp + "/ed_speed", y, "m s-1");
    putSeries(f, grp + "/ed_speed_error", e, "m s-1");
    putSeries(f, grp + "/ed_collision_phase", cmin, "1");
    putSeries(f, grp + "/hydro_speed", yh, "m s-1");
    writeTracked(f, grp, r.n_sweep[law]);
  }
  for (const ParameterSweep& sw : r.wet_sweeps) {
    std::vector<double> y, e, yh;
    for (const SweepPoint& s : sw.points) {
      y.push_back(s.ed.value);
      e.push_back(s.ed.error);
      yh.push_back(s.hydro.value);
    }
    const std::string grp = fmt::format("{}/{}_sweep", kRoot, sw.key);
    f.createGroup(grp);
    putSeries(f, grp + "/value", sw.values, "1");
    putSeries(f, grp + "/ed_speed", y, "m s-1");
    putSeries(f, grp + "/ed_speed_error", e, "m s-1");
    putSeries(f, grp + "/hydro_speed", yh, "m s-1");
  }
}

// Measured CPU times (they differ between any two executions) all live under /cost.
void writeCost(h5::File& f, const WaveFrontsConfig& c, const WaveFrontsResults& r) {
  const std::string grp = kRoot + "/cost";
  f.createGroup(grp);
  for (int law = 0; law < kLaws; ++law) {  // CPU seconds per answer over the N sweep
    std::vector<double> ed, hydro;
    for (const SweepPoint& p : r.n_sweep[law]) {
      ed.push_back(p.ed_cpu_per_cycle * c.answer_cycles);
      hydro.push_back(p.hydro_cpu);
    }
    putSeries(f, fmt::format("{}/per_answer_{}_ed_cpu_seconds", grp, kLawNames[law]), ed, "s");
    putSeries(f, fmt::format("{}/per_answer_{}_hydro_cpu_seconds", grp, kLawNames[law]), hydro,
              "s");
  }
  writeCostAccuracy(f, grp, r.cost);
}

}  // namespace

const TransitSpeeds& particleTransit(const SweepPoint& p, int i) {
  const TransitSpeeds& pooled = p.tracked.transit[i];
  if (pooled.speed.valid() || std::isfinite(pooled.lower_bound) || p.period2_seeds == 0)
    return pooled;
  return p.tracked_period2.transit[i];
}

bool peakJumps(const PhaseProfiles& p, const FrontEpisode& f, double limit) {
  const int n = p.phases();
  if (n <= 1 || p.front_height.size() != static_cast<std::size_t>(n)) return false;
  const int steps = ((f.last_phase - f.first_phase) % n + n) % n;
  for (int k = 0; k < steps; ++k) {
    const double a = p.front_height[static_cast<std::size_t>((f.first_phase + k) % n)];
    const double b = p.front_height[static_cast<std::size_t>((f.first_phase + k + 1) % n)];
    if (b - a > limit) return true;  // NaN (no peak) compares false
  }
  return false;
}

WaveFrontsResults analyseWaveFronts(const WaveFrontsConfig& c, const RunSet& runs) {
  WaveFrontsResults r;
  for (int law = 0; law < kLaws; ++law) r.paper[law] = paperLaw(c, runs, law);
  for (int law = 0; law < kLaws; ++law)
    for (int n : c.counts) {
      r.n_sweep[law].push_back(
          sweepPoint(runs, WaveFrontsConfig::particleRun(law, fmt::format("N={}", n)),
                     WaveFrontsConfig::hydroRun(law, fmt::format("N={}", n)), c.sweepCycles(law)));
      trackSweepPoint(c, runs, law, n, r.n_sweep[law].back());
    }
  r.wet_sweeps[0] = wetSweep(c, runs, "St_c", c.stokes);
  r.wet_sweeps[1] = wetSweep(c, runs, "e_inf", c.e_inf);
  r.cost = costAccuracy(c, runs, r.paper[1].ed.all);
  r.failures = analyseFailures(c, runs);
  for (int law = 0; law < kLaws; ++law) r.models[law] = analyseModels(c, runs, law);
  for (int law = 0; law < kLaws; ++law) r.states[law] = analyseStates(c, runs, law);
  if (c.lammps) r.lammps = analyseLammps(c, runs, r.paper[0].seed1, r.paper[0].hydro[0]);
  r.cheapest = cheapestModels(c, r);
  for (int law = 0; law < kLaws; ++law) r.budgets[law] = analyseBudgets(c, runs, law);
  return r;
}

void writeWaveFrontsResults(h5::File& f, const WaveFrontsConfig& c, const WaveFrontsResults& r) {
  f.createGroup(kRoot);
  for (int law = 0; law < kLaws; ++law) writePaper(f, law, r.paper[law]);
  writeSweeps(f, c, r);
  writeCost(f, c, r);
  writeFailures(f, kRoot, c, r.failures);
  for (int law = 0; law < kLaws; ++law) writeModels(f, kRoot, law, r.models[law]);
  for (int law = 0; law < kLaws; ++law) writeStates(f, kRoot, law, r.states[law]);
  if (r.lammps) writeLammps(f, kRoot, *r.lammps);
  writeCheapestModels(f, kRoot, r.cheapest);
  for (int law = 0; law < kLaws; ++law) writeBudgets(f, kRoot, law, r.budgets[law]);
}

}  // namespace granwave
