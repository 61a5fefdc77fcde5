#include "studies/particle_run/FieldsSetup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene/SceneDerived.hpp"
#include "studies/particle_run/VelocityFrontSummary.hpp"

namespace granwave {

PhaseAveragerConfig phaseAveragerConfig(const Scene& s, int P, int blocks, int fixed_discard) {
  if (s.drive.frequency <= 0)
    throw std::invalid_argument("phase-averaged fields need a driven scene (drive.frequency > 0)");
  const SceneDerived dv = derive(s);
  PhaseAveragerConfig c;
  c.grid = FieldGrid::forContainer(s.container.width, s.container.height, dv.amplitude,
                                   s.particles.diameter);
  c.samples_per_cycle = s.run.phases_per_cycle;
  c.cycles_per_window = P;
  c.blocks = blocks;
  c.total_cycles = static_cast<int>(std::floor(s.run.duration * s.drive.frequency + 1e-9));
  c.fixed_discard = fixed_discard;
  return c;
}

SurfaceRecorderConfig surfaceRecorderConfig(const Scene& s) {
  SurfaceRecorderConfig c;
  c.records_per_cycle = s.run.phases_per_cycle;
  c.width = s.container.width;
  c.diameter = s.particles.diameter;
  c.periodic_x = s.container.periodic_x;
  return c;
}

SurfaceWaveAnalysis surfaceWaves(const SurfaceRecorder& recorder, const PhaseAverager& averager) {
  return analyseSurfaceWaves(recorder.series(std::max(0, averager.firstPooledCycle())));
}

FieldsContext fieldsContext(const Scene& s, const std::string& source,
                            const std::string& scene_toml, int layer_period) {
  const SceneDerived dv = derive(s);
  FieldsContext c;
  c.diameter = s.particles.diameter;
  c.mass = dv.mass;
  c.inertia = dv.inertia;
  c.frequency = s.drive.frequency;
  c.amplitude = dv.amplitude;
  c.T0 = dv.T0;
  c.layer_period = layer_period;
  c.source = source;
  c.scene_toml = scene_toml;
  return c;
}

namespace {
// The state-conditioned fields: windows in each state and their impact fronts.
std::string formatStateFields(const FieldsAnalysis& a) {
  std::string r =
      fmt::format("by state        period 1 in {} and period 2 in {} windows of 12 cycles",
                  a.state_windows[0], a.state_windows[1]);
  for (const FieldsAnalysis& s : a.states) {
    r += fmt::format("; period-{} fronts", s.state_period);
    int n = 0;
    for (const FrontEpisode& e : s.fronts)
      if (e.from_impact)
        r += fmt::format("{} {:.2f} +- {:.2f} m/s", n++ ? "," : "", e.speed, e.speed_error);
    if (n == 0) r += " none";
  }
  return r + "\n";
}
}  // namespace

std::string formatFieldsSummary(const FieldsAnalysis& a) {
  std::string r;
  r += fmt::format("fields          {} x {} cells of {:.3g} m, {} phases ({} cycles x M = {})\n",
                   a.grid.nx, a.grid.nz, a.grid.wz, a.pooled.phases, a.cycles_per_window,
                   a.samples_per_cycle);
  r += fmt::format("pooled          {} steady cycles in {} blocks, {} transient cycles discarded\n",
                   a.pooled_cycles, a.blocks, a.discarded_cycles);
  if (a.state_windows[0] >= 0) r += formatStateFields(a);
  int impact_fronts = 0;
  for (const FrontEpisode& e : a.fronts) impact_fronts += e.from_impact;
  if (impact_fronts == 0)
    r += "fronts          none after an impact with T~_g/T0 > threshold over 3 or more phases\n";
  if (static_cast<int>(a.fronts.size()) > impact_fronts)
    r += fmt::format(
        "hot spots       {} episode(s) of T~_g/T0 > threshold away from the plate "
        "(not impact fronts; in the file with from_impact = 0)\n",
        a.fronts.size() - impact_fronts);
  if (a.patterns.available) {
    const PatternResult& p = a.patterns;
    r += fmt::format(
        "patterns        at t/T = {:.1f} over the last {} cycles: {}; surface wave {} (mode {}, "
        "{:.2f} d, alternation {:.2f}); {} kink(s); <|psi6|> {:.2f}, bonds kept {:.2f} over the "
        "cycles and {:.2f} per cycle, relative mobility {:.2f} d per cycle\n",
        p.phase, p.cycles, toString(p.state.state), p.surface_wave.detected ? "yes" : "no",
        p.surface_wave.mode, p.surface_wave.amplitude_d, p.surface_wave.alternation_fraction,
        p.kinks.kink_x.size(), p.state.mean_abs_psi6, p.state.bonds_kept,
        p.state.bonds_kept_per_cycle, p.state.mean_relative_displacement_d);
    const WithinCycleResult& w = p.within_cycle;
    r += fmt::format(
        "within a cycle  {} in {:.0f} % of {} cycles (crystal {:.0f} %, amorphous {:.0f} %, "
        "liquid-like {:.0f} %) at the most compact phase t/T = {:.1f}: {:.2f} neighbours, "
        "<|psi6|> {:.2f}; on the lid {:.1f} particles per cycle ({:.0f} % of cycles)\n",
        toString(w.state), 100 * std::max({w.crystal_share, w.amorphous_share, w.liquid_share}),
        w.cycles, 100 * w.crystal_share, 100 * w.amorphous_share, 100 * w.liquid_share,
        w.compact_phase, w.coordination, w.psi6, w.lid_row, 100 * w.lid_row_cycles);
  }
  if (a.surface.available) r += surfaceSpectrumLine(a.surface);
  for (const FrontEpisode& e : a.fronts) {
    if (!e.from_impact) continue;
    r += fmt::format(
        "front           t/T {:.2f}..{:.2f}: {:.2f} +- {:.2f} m/s (lab), {:.2f} m/s relative to "
        "the gas ahead; peak T~_g/T0 {:.2f}\n",
        static_cast<double>(e.first_phase) / a.samples_per_cycle,
        static_cast<double>(e.last_phase) / a.samples_per_cycle, e.speed, e.speed_error,
        e.speed_relative, e.peak_temperature);
  }
  return r + velocityFrontLines(a.profiles());
}

}  // namespace granwave
