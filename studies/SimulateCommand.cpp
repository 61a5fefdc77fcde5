#include "studies/SimulateCommand.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "coarse_grain/FieldsFile.hpp"
#include "coarse_grain/PhaseAverager.hpp"
#include "particles/EdSimulation.hpp"
#include "particles/H5mdWriter.hpp"
#include "particles/InitialState.hpp"
#include "scene/SceneParser.hpp"
#include "studies/FieldsSetup.hpp"
#include "studies/InterruptFlag.hpp"
#include "studies/ProgressReporter.hpp"
#include "studies/RunSummary.hpp"
#include "studies/Version.hpp"

namespace granwave {

namespace {

// Collects the centre-of-mass height at every record, for the period in the summary.
class CenterOfMassSeries : public SnapshotObserver {
 public:
  void observe(const Snapshot& s) override { height.push_back(s.obs.center_of_mass_height); }
  std::vector<double> height;
};

double totalEnergy(const Observables& o) {
  return o.kinetic_energy + o.rotational_energy + o.potential_energy;
}

}  // namespace

void addSimulateCommand(CLI::App& app, SimulateOptions& opt) {
  CLI::App* cmd = app.add_subcommand("simulate", "Run the event-driven particle engine on a scene");
  cmd->add_option("scene", opt.scene_path, "Scene file (TOML, SI units; see docs/scenes.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", opt.output, "Output run file (H5MD); default <scene>.h5");
  cmd->add_option("--set", opt.overrides, "Override a scene key: section.key=value")
      ->take_all()
      ->allow_extra_args(false);
  cmd->add_flag("-q,--quiet", opt.quiet, "No progress line on stderr");
  cmd->add_flag("--no-output", opt.no_output, "Do not write a run file (summary only)");
  cmd->add_option("--fields", opt.fields,
                  "Also write phase-averaged fields, computed live (HDF5 + .xdmf)");
  cmd->add_option("--fields-period", opt.fields_period, "Cycles per phase window for --fields")
      ->check(CLI::Range(1, 4));
  cmd->add_option("--fields-blocks", opt.fields_blocks, "Blocks of cycles for --fields")
      ->check(CLI::Range(2, 50));
}

int runSimulate(const SimulateOptions& opt, const std::string& command_line) {
  const Scene scene = parseSceneFile(opt.scene_path, opt.overrides);
  const EngineConfig config = engineConfig(scene);
  const InitialCondition init = initialCondition(scene, config);
  EdSimulation sim(config, init);

  std::string out = opt.output;
  if (out.empty()) out = std::filesystem::path(opt.scene_path).stem().string() + ".h5";

  std::unique_ptr<H5mdWriter> writer;
  if (!opt.no_output) {
    BoxInfo box{scene.container.width, scene.container.height, scene.particles.diameter,
                scene.container.periodic_x, scene.container.periodic_z};
    RunProvenance prov{kVersion, command_line, scene.run.seed, ""};
    writer = std::make_unique<H5mdWriter>(out, sceneToToml(scene), prov, box,
                                          scene.run.trajectory_stride);
    sim.addObserver(writer.get());
  }
  CenterOfMassSeries com;
  sim.addObserver(&com);
  std::unique_ptr<PhaseAverager> averager;
  std::unique_ptr<PatternSampler> patterns;
  if (!opt.fields.empty()) {
    averager = std::make_unique<PhaseAverager>(
        phaseAveragerConfig(scene, opt.fields_period, opt.fields_blocks, -1));
    patterns = std::make_unique<PatternSampler>(PatternSamplerConfig{scene.run.phases_per_cycle});
    sim.addObserver(averager.get());
    sim.addObserver(patterns.get());
  }
  ProgressReporter progress(scene.run.duration);
  if (!opt.quiet) sim.addObserver(&progress);

  const Snapshot first = sim.snapshot();
  const auto& interrupt = installInterruptFlag();
  const auto t0 = std::chrono::steady_clock::now();
  const RunStatus status = sim.run(&interrupt);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  progress.finish();

  const Snapshot last = sim.snapshot();
  RunSummaryInput in;
  in.scene = &scene;
  in.scene_name = opt.scene_path;
  in.final_obs = last.obs;
  in.simulated = status.time;
  in.wall = wall;
  in.tc = config.tc;
  in.completed = status.completed;
  in.com_height = std::move(com.height);
  in.initial_energy = totalEnergy(first.obs);
  in.energy_balance_error = std::abs(totalEnergy(last.obs) - in.initial_energy -
                                     last.obs.wall_work + last.obs.dissipated_energy);
  const std::string summary = formatRunSummary(in);

  if (writer) {
    const std::string stored = formatRunSummary(in, false);
    if (status.completed) {
      writer->finish(true, stored);
    } else {
      writer->finish(false, stored, out + ".interrupted");
    }
  }
  fmt::print("{}", summary);
  if (!status.completed) {
    fmt::print(stderr, "granwave: interrupted at t = {:.4f} s; partial run saved as {}\n",
               status.time,
               opt.no_output ? std::string("(nothing: --no-output)") : out + ".interrupted");
    return 130;
  }
  if (writer) fmt::print("output          {}\n", out);
  if (averager) {
    PeriodResult period;
    int discarded = 0;
    const int layer_period = summarisePeriod(in, period, discarded) ? period.period : 0;
    FieldsAnalysis a = analyseFields(*averager, fieldsContext(scene, "live: " + opt.scene_path,
                                                              sceneToToml(scene), layer_period));
    a.patterns = classifyPatterns(*patterns, scene.container.width, scene.particles.diameter,
                                  scene.container.periodic_x);
    writeFieldsFile(opt.fields, a);
    fmt::print("{}", formatFieldsSummary(a));
    fmt::print("fields output   {} (+ {})\n", opt.fields, xdmfSidecarPath(opt.fields));
  }
  return 0;
}

}  // namespace granwave
