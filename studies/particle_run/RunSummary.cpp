#include "studies/particle_run/RunSummary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "scene/SceneDerived.hpp"

namespace granwave {

namespace {
const char* lawName(RestitutionKind k) {
  switch (k) {
    case RestitutionKind::Constant:
      return "constant";
    case RestitutionKind::Dry:
      return "dry";
    case RestitutionKind::Wet:
      return "wet";
  }
  return "?";
}
}  // namespace

bool summarisePeriod(const RunSummaryInput& in, PeriodResult& out, int& discarded) {
  if (in.scene->drive.frequency <= 0) return false;
  try {
    const RunPeriod r = runPeriod(in.com_height, in.scene->run.phases_per_cycle);
    out = r.result;
    discarded = r.discarded;
  } catch (const std::invalid_argument&) {
    return false;
  }
  return true;
}

bool summarisePeriodDoubling(const RunSummaryInput& in, PeriodDoublingSeries& out) {
  PeriodResult p;
  int discarded = 0;
  if (!summarisePeriod(in, p, discarded)) return false;
  // A period can be found in fewer steady cycles than one window of the series needs (the
  // series starts at an even cycle): then the series is not determined, as in `fields`, and
  // an interrupted short run still exits 130 with its partial file.
  try {
    out = periodDoublingSeries(in.com_height, in.scene->run.phases_per_cycle, discarded);
  } catch (const std::invalid_argument&) {
    return false;
  }
  return true;
}

std::string formatPeriodDoubling(const PeriodDoublingSeries& s) {
  int n = 0;
  for (int v : s.period2) n += v;
  double threshold = 0;
  for (double t : s.threshold) threshold = std::max(threshold, t);
  return fmt::format(
      "period-2 state  f/2 strength above its noise threshold (0.1 to {:.3f}) in {} of {} "
      "windows of {} cycles (share {:.2f}, 95 % interval {:.2f}-{:.2f}, {:.1f} effective "
      "windows), {} switch(es)\n",
      threshold, n, s.period2.size(), s.window_cycles, s.period2_share, s.share_low, s.share_high,
      s.effective_windows, s.switches);
}

std::string formatRunSummary(const RunSummaryInput& in, bool include_timing) {
  const Scene& s = *in.scene;
  const SceneDerived dv = derive(s);
  const Observables& o = in.final_obs;
  std::string r;
  r += fmt::format("scene           {}\n", in.scene_name);
  r += fmt::format("particles       N = {}, d = {:g} m, restitution = {}", s.particles.count,
                   s.particles.diameter, lawName(s.contact.restitution));
  if (s.contact.restitution == RestitutionKind::Wet)
    r += fmt::format(" (e_inf = {:g}, St_c = {:g}, v_c = {:.4g} m/s)", s.contact.e_inf,
                     s.contact.stokes_critical, dv.v_c);
  if (s.contact.restitution == RestitutionKind::Dry)
    r += s.contact.kappa_units == KappaUnits::Si
             ? fmt::format(" (kappa = {:g})", s.contact.kappa)
             : fmt::format(" (kappa = {:g} in its unit, kappa_SI = {:.4g})", s.contact.kappa,
                           dv.kappa_si);
  if (s.contact.restitution == RestitutionKind::Constant)
    r += fmt::format(" (e = {:g})", s.contact.e);
  r += fmt::format(", mu = {:g}\n", s.contact.friction);
  if (dv.driven)
    r += fmt::format("drive           f = {:g} Hz, Gamma = {:.4g}, A = {:.4g} m, v0 = {:.4g} m/s\n",
                     s.drive.frequency, dv.gamma, dv.amplitude, dv.v0);
  r += fmt::format("TC model        {}\n",
                   in.tc > 0 ? fmt::format("t_c = {:.3g} s", in.tc) : std::string("off"));
  if (in.sleep_alarm_time >= 0)
    r += fmt::format(
        "sleep rule      switched on at t = {:.6f} s: a particle rattled in enduring "
        "contact (docs/physics.md, \"Resting contacts\", item 7)\n",
        in.sleep_alarm_time);
  r += fmt::format("simulated       {:.4g} s{}\n", in.simulated,
                   in.completed ? "" : " (interrupted)");
  if (include_timing) {
    r += fmt::format("wall time       {:.3f} s  ({:.3g} simulated s per wall s)\n", in.wall,
                     in.simulated / std::max(in.wall, 1e-9));
    r += fmt::format("events          {}  ({:.3g} per wall s)\n", o.events,
                     o.events / std::max(in.wall, 1e-9));
    if (in.checkpoints > 0)
      r += fmt::format("checkpoints     {} written, {:.3f} s of the wall time\n", in.checkpoints,
                       in.checkpoint_wall);
  } else {
    r += fmt::format("events          {}\n", o.events);
  }
  r += fmt::format("collisions      pair {}, wall {}, made elastic by TC {}, came to rest {}\n",
                   o.collisions.pair, o.collisions.wall, o.collisions.tc_elastic,
                   o.collisions.rests);
  r += fmt::format(
      "energy          dissipated {:.4g} J, work by walls {:.4g} J, balance error {:.2g} J\n",
      o.dissipated_energy, o.wall_work, in.energy_balance_error);
  PeriodResult p;
  int discarded = 0;
  if (summarisePeriod(in, p, discarded)) {
    r += fmt::format(
        "centre of mass  period {}T (subharmonic strength f/2: {:.3f}, f/3: {:.3f}, f/4: {:.3f}; "
        "threshold 0.1; {} cycles after {} discarded)\n",
        p.period, p.strength[2], p.strength[3], p.strength[4], p.cycles_used, discarded);
    PeriodDoublingSeries series;
    if (summarisePeriodDoubling(in, series)) r += formatPeriodDoubling(series);
  } else if (dv.driven) {
    r += "centre of mass  period not determined (fewer than 12 steady cycles)\n";
  }
  return r;
}

}  // namespace granwave
