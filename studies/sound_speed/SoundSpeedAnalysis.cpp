#include "studies/sound_speed/SoundSpeedAnalysis.hpp"

#include <fmt/format.h>

#include <cmath>

#include "coarse_grain/FieldsReader.hpp"
#include "hydro/ShockRelations.hpp"
#include "hydro/SoundSpeed.hpp"
#include "scene/SceneDerived.hpp"
#include "studies/contract/StudyResults.hpp"
#include "studies/hydro_run/HydroModel.hpp"

namespace granwave {

namespace {

const std::string kRoot = "/results/sound_speed";

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

double spread(const std::vector<double>& v) { return meanAndStandardError(v).error; }

// One impact front of a run: its states, w, and each theory with its spread over the blocks.
FrontComparison compare(const SoundSpeedConfig& c, const std::string& run,
                        const FieldsRecord& fields, const FrontEpisode& fr, double mass,
                        const hydro::RestitutionClosure& closure) {
  const PhaseProfiles& p = fields.profiles;
  FrontComparison cmp;
  cmp.run = run;
  cmp.start = p.start(fr);
  cmp.T0 = fields.context.T0;
  const std::vector<int> phases = episodePhases(p, fr.first_phase);
  cmp.states = frontStates(p, phases, c.rows, c.gap);
  if (!cmp.states.ahead.valid || !cmp.states.behind.valid) {
    cmp.outcome = FrontComparison::Outcome::NoState;
    return cmp;
  }
  std::vector<std::array<double, kTheories>> per_block;
  std::vector<double> ua_block;
  for (int b = 0; b < fields.blocks; ++b) {
    const FrontStates sb = frontStates(p, phases, c.rows, c.gap, b);
    per_block.push_back(predictions(sb, mass, closure));
    ua_block.push_back(sb.ahead.valid ? sb.ahead.uz : NAN);
  }
  const double ua_err = spread(ua_block);
  cmp.w = {fr.speed - cmp.states.ahead.uz,
           std::hypot(fr.speed_error, std::isfinite(ua_err) ? ua_err : 0.0)};
  const auto pred = predictions(cmp.states, mass, closure);
  for (int k = 0; k < kTheories; ++k) {
    std::vector<double> vb;
    for (const auto& b : per_block) vb.push_back(b[static_cast<std::size_t>(k)]);
    cmp.theory[k] = {pred[k], spread(vb)};
    const double z = sigmaDistance(cmp.w, cmp.theory[k]);
    cmp.holds[k] = std::isfinite(z) && std::abs(z) <= 2;
  }
  return cmp;
}

void tally(const FrontComparison& cmp, SoundSpeedResults& r) {
  r.front_speed_relative.push_back(cmp.w.value);
  r.mach_number.push_back(cmp.w.value / cmp.theory[0].value);
  for (int k = 0; k < kTheories; ++k) {
    const Measurement& m = cmp.theory[k];
    if (!m.valid()) continue;
    TheorySeries& t = r.theories[k];
    ++t.tested;
    if (cmp.holds[k]) ++t.holds;
    t.predicted.push_back(m.value);
    t.predicted_error.push_back(std::isfinite(m.error) ? m.error : 0.0);
    t.measured.push_back(cmp.w.value);
    t.measured_error.push_back(cmp.w.error);
  }
}

// Every impact front of one run (or the run's failure).
void compareRun(const SoundSpeedConfig& c, const RunSet& runs, const std::string& name, int law,
                SoundSpeedResults& r) {
  const RunRecord& run = runs.get(name);
  if (!run.ok) {
    FrontComparison failed;
    failed.outcome = FrontComparison::Outcome::RunFailed;
    failed.run = name;
    failed.failure = run.message;
    r.fronts.push_back(failed);
    return;
  }
  const hydro::RestitutionClosure closure = restitutionClosure(c.scenes.base[law]);
  const double mass = derive(c.scenes.base[law]).mass;
  const FieldsRecord p = readFieldsFile(run.fieldsPath());
  for (const FrontEpisode& fr : p.profiles.fronts) {
    if (!fr.from_impact || !std::isfinite(fr.speed)) continue;
    r.fronts.push_back(compare(c, name, p, fr, mass, closure));
    if (r.fronts.back().outcome == FrontComparison::Outcome::Compared) tally(r.fronts.back(), r);
  }
}

}  // namespace

SoundSpeedResults analyseSoundSpeed(const SoundSpeedConfig& c, const RunSet& runs) {
  SoundSpeedResults r;
  for (int law = 0; law < kLaws; ++law)
    for (int n : c.counts)
      for (double gamma : c.gammas)
        compareRun(c, runs, SoundSpeedConfig::label(law, n, gamma), law, r);
  return r;
}

void writeSoundSpeedResults(h5::File& f, const SoundSpeedResults& r) {
  f.createGroup(kRoot);
  for (int k = 0; k < kTheories; ++k) {
    const TheorySeries& t = r.theories[k];
    if (t.predicted.empty()) continue;
    const std::string grp = fmt::format("{}/theory_{}", kRoot, k);
    f.createGroup(grp);
    f.writeStringAttribute(grp, "name", kTheoryNames[k]);
    putSeries(f, grp + "/predicted", t.predicted, "m s-1");
    putSeries(f, grp + "/predicted_error", t.predicted_error, "m s-1");
    putSeries(f, grp + "/measured", t.measured, "m s-1");
    putSeries(f, grp + "/measured_error", t.measured_error, "m s-1");
    putValue(f, grp, "fronts_tested", t.tested);
    putValue(f, grp, "fronts_where_it_holds", t.holds);
  }
  putSeries(f, kRoot + "/front_speed_relative", r.front_speed_relative, "m s-1");
  putSeries(f, kRoot + "/mach_number", r.mach_number, "1");
}

}  // namespace granwave
