// CPU per drive cycle of the continuum solver (docs/performance.md, "Hydrodynamic solver").
//
//  BM_HydroCycle/<dry|wet>_<smooth|rough>  the paper's scene (scenes/paper-dry.toml and
//      paper-wet.toml, hydro.particles as named), 100 cells, rtol 1e-4, as `granwave hydro`
//      sets it up: from the settled layer, the drive ramped up over two cycles, then six more,
//      a fixed 8 cycles (the dry smooth scene reaches its periodic state there). Timed: the
//      whole integration, thread CPU. Counters per drive cycle: cpu_s, CVODE steps,
//      right-hand sides, Jacobians, Newton convergence failures and error-test failures.
//
// Only the public hydro/ interface is used, so the same file builds against an older solver
// for paired runs (bench/pair_hydro_bench.py).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "hydro/HydroSimulation.hpp"
#include "scene/SceneDerived.hpp"
#include "scene/SceneParser.hpp"

namespace {

namespace hydro = granwave::hydro;
using granwave::Scene;

constexpr int kCycles = 8;

// The scene's closures as `granwave hydro` maps them (studies/cli/HydroCommand.cpp).
hydro::ConstitutiveModel constitutiveModel(const Scene& s, const granwave::SceneDerived& dv) {
  hydro::ConstitutiveModel m;
  m.mass = dv.mass;
  m.sigma = s.particles.diameter;
  m.restitution = s.contact.restitution == granwave::RestitutionKind::Dry
                      ? hydro::RestitutionClosure::dry(dv.kappa_si)
                      : hydro::RestitutionClosure::wet(s.contact.e_inf, dv.v_c);
  m.wall_restitution = m.restitution;
  m.knudsen_length = m.sigma;
  m.contact.scale = s.hydro.contact_pressure * hydro::kHexagonalClosePacking * dv.mass /
                    m.diskArea() * s.run.gravity * m.sigma;
  if (s.hydro.particles == granwave::HydroParticles::Rough)
    m.rough = hydro::RoughParticles{true, s.contact.friction, s.contact.tangential_limit, 0.4};
  return m;
}

void BM_HydroCycle(benchmark::State& state, const std::string& law, const std::string& particles) {
  const Scene s =
      granwave::parseSceneFile(std::string(GRANWAVE_SCENE_DIR) + "/paper-" + law + ".toml",
                               {"hydro.particles=\"" + particles + "\""});
  const granwave::SceneDerived dv = granwave::derive(s);
  hydro::HydroGeometry g;
  g.cells = s.hydro.cells;
  g.height = s.container.height;
  g.gravity = s.run.gravity;
  g.amplitude = dv.amplitude;
  g.omega = dv.omega;
  g.ramp_time = 2.0 / s.drive.frequency;
  const hydro::GranularHydro1D pde(g, constitutiveModel(s, dv),
                                   s.particles.count * dv.mass / s.container.width);
  hydro::HydroRunOptions o;
  o.samples_per_cycle = s.run.phases_per_cycle;
  o.max_cycles = kCycles;
  o.min_cycles = kCycles - 2;  // after the two ramp cycles: the run never stops early
  o.cvode.rtol = s.hydro.rtol;
  o.atol_scale = s.hydro.atol;
  double cpu = 0, cycles = 0, steps = 0, rhs = 0, jac = 0, ncf = 0, etf = 0;
  for (auto _ : state) {
    hydro::HydroSimulation sim(pde, o);
    hydro::HydroResult r;
    try {
      r = sim.run();
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
    cpu += r.cpu_seconds;
    cycles += r.cycles;
    steps += static_cast<double>(r.stats.steps);
    rhs += static_cast<double>(r.stats.rhs_evals);
    jac += static_cast<double>(r.stats.jac_evals);
    ncf += static_cast<double>(r.stats.nonlin_conv_fails);
    etf += static_cast<double>(r.stats.err_test_fails);
  }
  cycles = std::max(cycles, 1.0);
  state.counters["cpu_s_per_cycle"] = cpu / cycles;
  state.counters["steps_per_cycle"] = steps / cycles;
  state.counters["rhs_per_cycle"] = rhs / cycles;
  state.counters["jac_per_cycle"] = jac / cycles;
  state.counters["ncf_per_cycle"] = ncf / cycles;
  state.counters["etf_per_cycle"] = etf / cycles;
}

}  // namespace

BENCHMARK_CAPTURE(BM_HydroCycle, dry_smooth, std::string("dry"), std::string("smooth"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_HydroCycle, dry_rough, std::string("dry"), std::string("rough"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_HydroCycle, wet_smooth, std::string("wet"), std::string("smooth"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_HydroCycle, wet_rough, std::string("wet"), std::string("rough"))
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

BENCHMARK_MAIN();
