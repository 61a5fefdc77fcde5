#include "studies/SimulateCommand.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <ctime>
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
#include "studies/RunCache.hpp"
#include "studies/RunCheckpoint.hpp"
#include "studies/RunSummary.hpp"
#include "studies/Version.hpp"

namespace granwave {

namespace {

// Collects the centre-of-mass height at every record, for the period in the summary.
class CenterOfMassSeries : public SnapshotObserver, public Checkpointable {
 public:
  void observe(const Snapshot& s) override { height.push_back(s.obs.center_of_mass_height); }
  void saveState(h5::File& file, const std::string& group) const override {
    file.createGroup(group);
    file.writeDataset(group + "/height", height, {height.size()});
  }
  void restoreState(const h5::File& file, const std::string& group) override {
    height = file.readDataset<double>(group + "/height");
  }
  std::vector<double> height;
};

// What a checkpoint may only be continued by: the same resolved scene, the same outputs and
// the same build (another build need not give the same bits).
std::string runIdentity(const Scene& scene, const SimulateOptions& opt) {
  return fmt::format("{}\nrun_file={} fields={} fields_period={} fields_blocks={}\nbuild={}\n",
                     sceneToToml(scene), !opt.no_output, !opt.fields.empty(), opt.fields_period,
                     opt.fields_blocks, buildIdentity());
}

double processCpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

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
  cmd->add_option("--checkpoint-every", opt.checkpoint_every,
                  "Save a checkpoint every this many seconds of wall time (and on Ctrl-C); "
                  "the same command then continues a killed run from it")
      ->check(CLI::PositiveNumber);
}

int runSimulate(const SimulateOptions& opt, const std::string& command_line) {
  const Scene scene = parseSceneFile(opt.scene_path, opt.overrides);
  const EngineConfig config = engineConfig(scene);
  std::string out = opt.output;
  if (out.empty()) out = std::filesystem::path(opt.scene_path).stem().string() + ".h5";

  // Observers that accumulate over the run; a checkpoint saves them by these names.
  CenterOfMassSeries com;
  std::unique_ptr<PhaseAverager> averager;
  std::unique_ptr<PatternSampler> patterns;
  NamedCheckpointables accumulating{{"center_of_mass", &com}};
  if (!opt.fields.empty()) {
    averager = std::make_unique<PhaseAverager>(
        phaseAveragerConfig(scene, opt.fields_period, opt.fields_blocks, -1));
    patterns = std::make_unique<PatternSampler>(PatternSamplerConfig{scene.run.phases_per_cycle});
    accumulating.emplace_back("phase_averager", averager.get());
    accumulating.emplace_back("patterns", patterns.get());
  }

  std::unique_ptr<RunCheckpoint> checkpoint;
  LoadedCheckpoint loaded;
  bool resumed = false;
  if (opt.checkpoint_every > 0) {
    checkpoint = std::make_unique<RunCheckpoint>(out, runIdentity(scene, opt));
    removeOrphanedTemporaries(out);
    if (!opt.fields.empty()) removeOrphanedTemporaries(opt.fields);
    if (checkpoint->exists()) {
      loaded = checkpoint->load(accumulating);
      resumed = true;
    }
  }
  std::unique_ptr<EdSimulation> simulation =
      resumed ? std::make_unique<EdSimulation>(config, loaded.engine)
              : std::make_unique<EdSimulation>(config, initialCondition(scene, config));
  EdSimulation& sim = *simulation;
  if (resumed)
    fmt::print(stderr, "granwave: continuing from {} at t = {:.4f} s (checkpoint {})\n",
               checkpoint->statePath(), sim.now(), loaded.ledger.checkpoints);

  std::unique_ptr<H5mdWriter> writer;
  if (!opt.no_output) {
    BoxInfo box{scene.container.width, scene.container.height, scene.particles.diameter,
                scene.container.periodic_x, scene.container.periodic_z};
    if (resumed) {
      writer = std::make_unique<H5mdWriter>(out, loaded.run_copy, box, scene.run.trajectory_stride);
    } else {
      RunProvenance prov{kVersion, command_line, scene.run.seed, ""};
      writer = std::make_unique<H5mdWriter>(out, sceneToToml(scene), prov, box,
                                            scene.run.trajectory_stride);
    }
    sim.addObserver(writer.get());
  }
  sim.addObserver(&com);
  if (averager) {
    sim.addObserver(averager.get());
    sim.addObserver(patterns.get());
  }
  ProgressReporter progress(scene.run.duration);
  if (!opt.quiet) sim.addObserver(&progress);

  const double initial_energy =
      resumed ? loaded.ledger.initial_energy : totalEnergy(sim.snapshot().obs);
  const auto& interrupt = installInterruptFlag();
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = processCpuSeconds();
  auto secondsSince = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  int checkpoints_written = 0;
  double checkpoint_wall = 0;
  auto saveCheckpoint = [&] {
    const auto started = std::chrono::steady_clock::now();
    CheckpointLedger ledger = loaded.ledger;
    ledger.initial_energy = initial_energy;
    ledger.wall_seconds += secondsSince(t0);
    ledger.cpu_seconds += processCpuSeconds() - cpu0;
    loaded.ledger.checkpoints = checkpoint->save(sim, writer.get(), accumulating, ledger);
    ++checkpoints_written;
    checkpoint_wall += secondsSince(started);
  };
  auto last_checkpoint = std::chrono::steady_clock::now();
  const auto checkpointDue = [&] {
    return checkpoint && secondsSince(last_checkpoint) >= opt.checkpoint_every;
  };
  RunStatus status;
  while (true) {
    try {
      status = sim.run(&interrupt, checkpointDue);
    } catch (...) {
      // The engine's failures (collapse, stall) repeat from any checkpoint: they are the
      // run's result, and a checkpoint would only make the next attempt fail again later.
      if (checkpoint) checkpoint->remove();
      throw;
    }
    if (!status.paused) break;
    saveCheckpoint();
    last_checkpoint = std::chrono::steady_clock::now();
  }
  // Nothing is lost on Ctrl-C: the same command continues from here.
  if (status.interrupted && checkpoint) saveCheckpoint();
  // A finished simulation needs no checkpoint once the function returns, whether its
  // outputs are written or their analysis fails (that failure would only repeat). A kill
  // before then continues from the last checkpoint.
  struct RemoveWhenFinished {
    RunCheckpoint* checkpoint;
    std::string partial;  // RUN.h5.interrupted of an earlier Ctrl-C, superseded
    ~RemoveWhenFinished() {
      if (!checkpoint) return;
      checkpoint->remove();
      std::error_code ec;
      std::filesystem::remove(partial, ec);
    }
  } remove_when_finished{status.completed ? checkpoint.get() : nullptr, out + ".interrupted"};
  const double wall = loaded.ledger.wall_seconds + secondsSince(t0);
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
  in.initial_energy = initial_energy;
  in.checkpoints = checkpoints_written;
  in.checkpoint_wall = checkpoint_wall;
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
    fmt::print(stderr, "granwave: interrupted at t = {:.4f} s; partial run saved as {}{}\n",
               status.time,
               opt.no_output ? std::string("(nothing: --no-output)") : out + ".interrupted",
               checkpoint ? "; the same command continues from " + checkpoint->statePath() : "");
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
