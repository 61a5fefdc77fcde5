#include "studies/cli/HydroCommand.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>

#include "coarse_grain/FieldsFile.hpp"
#include "files/OutputPath.hpp"
#include "scene/SceneParser.hpp"
#include "studies/cli/OptionChecks.hpp"
#include "studies/hydro_run/Hydro2DRun.hpp"
#include "studies/hydro_run/HydroRun.hpp"
#include "studies/particle_run/VelocityFrontSummary.hpp"
#include "studies/run_files/HydroRunFile.hpp"
#include "studies/runner/InterruptFlag.hpp"

namespace granwave {

namespace {

// Per drive cycle over the window, in mJ, with each loss's share of the dissipation.
void printBudget(const RunEnergyBudget& budget, int window_cycles) {
  if (budget.empty()) return;
  const RunEnergyBudget::PerCycle p = budget.perCycle(window_cycles);
  fmt::print(
      "energy          per cycle: plate work {:.3f} mJ; lost {:.3f} mJ: pair collisions {:.0f} %, "
      "friction and rotation {:.0f} %, walls {:.0f} %; closure {:.1e} mJ\n",
      p.work, p.lost(), 100 * p.pair / p.lost(), 100 * p.friction / p.lost(),
      100 * p.wall / p.lost(), p.closure);
}

void printSummary(const HydroOptions& opt, const Scene& scene, const HydroRunContent& c,
                  const std::string& out) {
  fmt::print("scene           {}\n", opt.scene_path);
  fmt::print(
      "hydro           {} cells, {} transport, {} particles, restitution {}, {} walls, rtol {:g}\n",
      scene.hydro.cells,
      scene.hydro.transport == HydroTransport::GarzoDufty ? "Garzo-Dufty" : "Jenkins-Richman",
      scene.hydro.particles == HydroParticles::Rough ? "rough" : "smooth",
      scene.hydro.restitution_model == HydroRestitutionModel::Constant
          ? "constant"
          : "velocity-dependent (Maxwell-averaged)",
      scene.hydro.walls == HydroWalls::Hard ? "hard" : "spring", scene.hydro.rtol);
  fmt::print("periodic state  {} after {} cycles; centre-of-mass period {}\n",
             c.periodic ? "reached" : "NOT reached", c.cycles,
             c.periodic ? fmt::format("{}T", c.period) : std::string("unknown"));
  fmt::print("layer           {}\n", c.regime);
  fmt::print(
      "cost            {:.2f} CPU-s ({:.3f} per cycle), {} steps, {} RHS evaluations, "
      "{} Jacobians, {} error-test and {} nonlinear failures\n",
      c.cpu_seconds, c.cpu_seconds / c.cycles, c.steps, c.rhs_evals, c.jacobian_evals,
      c.error_test_failures, c.nonlinear_failures);
  const int samples_per_cycle = scene.run.phases_per_cycle;
  for (const FrontEpisode& e : c.lab.fronts) {
    if (!e.from_impact) continue;
    fmt::print(
        "front           t/T {:.2f}..{:.2f}: {:.2f} +- {:.2f} m/s (lab, fit error); peak T/T0 "
        "{:.2f}\n",
        static_cast<double>(e.first_phase) / samples_per_cycle,
        static_cast<double>(e.last_phase) / samples_per_cycle, e.speed, e.fit_error,
        e.peak_temperature);
  }
  fmt::print("{}", velocityFrontLines(c.lab));
  printBudget(c.budget, c.windowCycles());
  fmt::print("output          {}\n", out);
}

void print2DSummary(const HydroOptions& opt, const Hydro2DRunContent& c, const std::string& out) {
  fmt::print("scene           {}\n", opt.scene_path);
  fmt::print("hydro 2D        {} columns x {} cells over {:g} m, {}, rtol {:g}\n", c.columns,
             c.cells, c.width, c.periodic ? "periodic" : "side walls", c.rtol);
  fmt::print("mass            conserved to {:.1e}\n", c.mass_drift);
  fmt::print(
      "cost            {:.2f} CPU-s ({:.3f} per cycle, {} cycles), {} steps, {} RHS evaluations, "
      "{} linear iterations, {} preconditioner Jacobians\n",
      c.cpu_seconds, c.cpu_seconds / static_cast<double>(c.cycles), c.cycles, c.steps, c.rhs_evals,
      c.linear_iterations, c.preconditioner_jacobians);
  fmt::print("remaps          {} (hydro.remap_share), {:.3g} J/m moved into heat\n", c.remaps,
             c.remap_heat);
  if (!c.budget.empty()) printBudget(c.budget, c.windowCycles());
  if (c.surface.available)
    fmt::print("{}", surfaceSpectrumLine(c.surface));
  else
    fmt::print("surface spectrum none: no whole window of cycles in the run's second half\n");
  fmt::print("output          {} (ParaView: {})\n", out, xdmfSidecarPath(out));
}

int run2D(const HydroOptions& opt, const Scene& scene, const std::string& out) {
  files::requireDistinct({{"scene", opt.scene_path}},
                         {{"hydro run file", out}, {"XDMF sidecar", xdmfSidecarPath(out)}});
  const Hydro2DRunContent content =
      runHydro2DScene(scene, opt.scene_path, opt.quiet ? nullptr : stderr);
  writeHydro2DRunFile(out, content);
  print2DSummary(opt, content, out);
  return 0;
}

}  // namespace

void addHydroCommand(CLI::App& app, HydroOptions& opt) {
  CLI::App* cmd = app.add_subcommand(
      "hydro",
      "Integrate the granular hydrodynamics of a scene (1D, or x-z with hydro.dimensions = 2)");
  cmd->add_option("scene", opt.scene_path, "Scene file (TOML; [hydro] keys, docs/scenes.md)")
      ->required()
      ->check(regularInputFile());
  cmd->add_option("-o,--output", opt.output, "Output file (HDF5); default <scene>.hydro.h5");
  cmd->add_option("--set", opt.overrides,
                  "Override a scene key: section.key=value (repeatable; default: none)")
      ->take_all();
  cmd->add_flag("-q,--quiet", opt.quiet, "No progress output");
}

int runHydro(const HydroOptions& opt) {
  const Scene scene = parseSceneFile(opt.scene_path, opt.overrides);
  std::string out = opt.output;
  if (out.empty()) out = std::filesystem::path(opt.scene_path).stem().string() + ".hydro.h5";
  if (scene.hydro.dimensions == 2) return run2D(opt, scene, out);
  files::requireDistinct({{"scene", opt.scene_path}}, {{"hydro run file", out}});
  // SIGINT/SIGTERM end the run at the next phase with exit 130, nothing written.
  const std::atomic<bool>& interrupt = installInterruptFlag();
  const HydroRunContent content =
      runHydroScene(scene, opt.scene_path, opt.quiet ? nullptr : stderr, &interrupt);
  if (interrupt.load()) throw hydro::HydroInterrupted("interrupted; nothing written");
  writeHydroRunFile(out, content);  // atomic: an interrupt now waits for the whole file
  if (interrupt.load())
    throw hydro::HydroInterrupted("interrupted once " + out + " was written (it is complete)");
  printSummary(opt, scene, content, out);
  return 0;
}

}  // namespace granwave
