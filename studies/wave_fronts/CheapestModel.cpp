// The cheapest model that reproduces the particles, scene by scene (docs/studies.md, "Cost per
// answer at equal accuracy").
#include "studies/wave_fronts/CheapestModel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "coarse_grain/PeriodDoublingSeries.hpp"  // kZ95
#include "studies/contract/FailureReason.hpp"
#include "studies/contract/StudyResults.hpp"
#include "studies/wave_fronts/WaveFrontsAnalysis.hpp"

namespace granwave {

namespace {

// (v - ref) / ref with both errors: the accuracy axis.
Measurement relativeGap(const Measurement& v, const Measurement& ref) {
  if (!v.valid() || !ref.valid() || ref.value == 0) return {};
  const double ev = std::isfinite(v.error) ? v.error : 0.0;
  const double er = std::isfinite(ref.error) ? ref.error : 0.0;
  return {(v.value - ref.value) / ref.value, std::hypot(ev, er) / std::abs(ref.value)};
}

ModelCost reference(const std::string& periods, const Measurement& speed, double cpu) {
  ModelCost m;
  m.model = "particles, full model";
  m.reference = true;
  m.cpu = cpu;
  m.speed = speed;
  if (speed.valid()) m.gap = {0.0, std::abs(speed.error / speed.value)};
  m.periods = periods;
  m.match = Match::yes;
  m.why = "the reference";
  return m;
}

// The paper's scene of one law: the full particle model and the hierarchy's candidates.
SceneCost paperScene(const WaveFrontsConfig& c, const ModelHierarchy& h, int law) {
  SceneCost s;
  s.scene = fmt::format("paper's scene, {}", kLawNames[law]);
  s.models.push_back(
      reference(h.reference_periods, h.reference, h.reference_cpu_per_cycle * c.answer_cycles));
  for (const ModelCandidate& cand : h.candidates) {
    ModelCost m;
    m.model = cand.description;
    m.continuum = cand.key.rfind("hydro", 0) == 0;
    m.failed = cand.failed;
    // The run's CPU time as recorded (the particles' too); a failed run gave no answer.
    m.cpu = cand.failed ? NAN : m.continuum ? cand.run_cpu : cand.cpu_per_cycle * c.answer_cycles;
    m.speed = cand.speed;
    m.gap = relativeGap(cand.speed, h.reference);
    m.periods = cand.periods;
    m.match = cand.failed ? Match::no : cand.match;
    m.why = cand.failed           ? cand.failure
            : !cand.speed.valid() ? "no resolved front"
                                  : "front speed and time in the period-2 state";
    s.models.push_back(m);
  }
  return s;
}

std::string joined(const std::vector<int>& v) {
  std::string out;
  for (int x : v) out += (out.empty() ? "" : ", ") + (x > 0 ? std::to_string(x) : "none");
  return out;
}

// One count of the N sweep: the particles over the sweep's seeds against the continuum with the
// velocity-dependent closure.
SceneCost sweepScene(const WaveFrontsConfig& c, const SweepPoint& p, int law, int count) {
  SceneCost s;
  s.scene = fmt::format("N = {}, {}", count, kLawNames[law]);
  ModelCost ref =
      reference(joined(p.seed_periods), p.tracked.speed, p.ed_cpu_per_cycle * c.answer_cycles);
  if (!p.tracked.speed.valid())
    ref.why = std::isfinite(p.tracked.lower_bound)
                  ? fmt::format(
                        "the reference; its front crosses the layer faster than the "
                        "phases resolve (> {:.3g} m/s)",
                        p.tracked.lower_bound)
                  : "the reference; no front speed: " + p.tracked.why_none;
  s.models.push_back(ref);
  ModelCost m;
  m.model = "hydro, velocity-dependent closure, Jenkins-Richman";
  m.continuum = true;
  m.failed = !p.hydro_ok;
  m.cpu = p.hydro_ok ? p.hydro_cpu : NAN;
  m.speed = p.hydro_tracked.speed;
  m.gap = relativeGap(m.speed, p.tracked.speed);
  m.periods = p.hydro_ok ? joined({p.hydro_period}) : "";
  if (m.failed) {
    m.match = Match::no;
    m.why = "failed: " + shortReason(p.hydro_failure);
  } else {
    m.match = sweepMatch(m.speed, p.hydro_period, p.tracked.speed, p.tracked.lower_bound,
                         p.seed_periods, c.front_tolerance, m.why);
  }
  s.models.push_back(m);
  return s;
}

}  // namespace

Match sweepMatch(const Measurement& v, int period, const Measurement& ref, double bound,
                 const std::vector<int>& periods, double tolerance, std::string& why) {
  if (!v.valid()) {
    why = "no resolved front";
    return Match::no;
  }
  bool agree = !periods.empty() && periods.front() > 0;
  for (int q : periods) agree = agree && q == periods.front();
  if (agree && period != periods.front()) {
    why = fmt::format("period {} against the particles' {}",
                      period > 0 ? std::to_string(period) : std::string("none"), periods.front());
    return Match::no;
  }
  const bool among = std::find(periods.begin(), periods.end(), period) != periods.end();
  if (!agree && !among) {
    why = "the seeds' periods differ and the continuum's is none of them";
    return Match::not_yet;
  }
  const std::string period_note =
      agree ? "front speed and period" : "front speed, and a period one of the seeds has";
  if (ref.valid()) {
    why = period_note;
    return frontMatch(v, ref, tolerance, true);
  }
  const double own = std::isfinite(v.error) ? v.error : 0.0;
  if (std::isfinite(bound) && v.value + kZ95 * own < (1 - tolerance) * bound) {
    why = fmt::format("slower than the particles' lower bound {:.3g} m/s", bound);
    return Match::no;
  }
  why = std::isfinite(bound)
            ? fmt::format("the particles give only a lower bound, {:.3g} m/s", bound)
            : std::string("the particles' front is not resolved");
  return Match::not_yet;
}

void pickCheapest(SceneCost& s) {
  s.cheapest = 0;
  s.cheaper_open.clear();
  // Without the particles' own cost nothing can be shown to be cheaper than them.
  if (s.models.empty() || !std::isfinite(s.models.front().cpu)) return;
  for (std::size_t i = 1; i < s.models.size(); ++i) {
    const ModelCost& m = s.models[i];
    if (m.match != Match::yes || !std::isfinite(m.cpu)) continue;
    if (m.cpu < s.models[static_cast<std::size_t>(s.cheapest)].cpu)
      s.cheapest = static_cast<int>(i);
  }
  const double limit = s.models.empty() ? NAN : s.models[static_cast<std::size_t>(s.cheapest)].cpu;
  for (std::size_t i = 1; i < s.models.size(); ++i) {
    const ModelCost& m = s.models[i];
    const bool open = m.match == Match::not_yet || m.match == Match::cannot_tell;
    if (open && std::isfinite(m.cpu) && !(m.cpu >= limit))
      s.cheaper_open.push_back(static_cast<int>(i));
  }
}

std::vector<SceneCost> cheapestModels(const WaveFrontsConfig& c, const WaveFrontsResults& r) {
  std::vector<SceneCost> out;
  for (int law = 0; law < kLaws; ++law) out.push_back(paperScene(c, r.models[law], law));
  for (int law = 0; law < kLaws; ++law)
    for (std::size_t i = 0; i < c.counts.size() && i < r.n_sweep[law].size(); ++i)
      out.push_back(sweepScene(c, r.n_sweep[law][i], law, c.counts[i]));
  for (SceneCost& s : out) pickCheapest(s);
  return out;
}

void writeCheapestModels(h5::File& f, const std::string& root,
                         const std::vector<SceneCost>& scenes) {
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const SceneCost& s = scenes[k];
    const std::string g = fmt::format("{}/cost/cheapest/scene_{}", root, k);
    std::vector<double> cpu, speed, speed_error, gap, gap_error;
    std::string models, reproduces, open;
    for (const ModelCost& m : s.models) {
      cpu.push_back(m.cpu);
      speed.push_back(m.speed.value);
      speed_error.push_back(m.speed.error);
      gap.push_back(m.gap.value);
      gap_error.push_back(m.gap.error);
      models += (models.empty() ? "" : "; ") + m.model;
      reproduces +=
          (reproduces.empty() ? "" : "; ") + (m.failed ? "no (fails)" : matchText(m.match));
    }
    for (int i : s.cheaper_open)
      open += (open.empty() ? "" : "; ") + s.models[static_cast<std::size_t>(i)].model;
    f.createGroup(g);
    putSeries(f, g + "/cpu_seconds_per_answer", cpu, "s");
    putSeries(f, g + "/front_speed", speed, "m s-1");
    putSeries(f, g + "/front_speed_error", speed_error, "m s-1");
    putSeries(f, g + "/front_difference", gap, "1");
    putSeries(f, g + "/front_difference_error", gap_error, "1");
    f.writeStringAttribute(g, "scene", s.scene);
    f.writeStringAttribute(g, "models", models);
    f.writeStringAttribute(g, "reproduces", reproduces);
    f.writeStringAttribute(g, "cheapest", s.models[static_cast<std::size_t>(s.cheapest)].model);
    f.writeStringAttribute(g, "cheaper_but_open", open);
  }
}

}  // namespace granwave
