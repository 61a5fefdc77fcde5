#include "studies/cli/SimulateCommand.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "coarse_grain/FieldsFile.hpp"
#include "coarse_grain/PhaseAverager.hpp"
#include "files/OutputPath.hpp"
#include "particles/EdSimulation.hpp"
#include "particles/H5mdWriter.hpp"
#include "particles/InitialState.hpp"
#include "particles/PairImpactHistogram.hpp"
#include "scene/SceneParser.hpp"
#include "studies/cli/FieldsSetup.hpp"
#include "studies/cli/OptionChecks.hpp"
#include "studies/cli/OutsideFailure.hpp"
#include "studies/cli/ProgressReporter.hpp"
#include "studies/cli/RunSummary.hpp"
#include "studies/cli/Version.hpp"
#include "studies/run_files/RunCheckpoint.hpp"
#include "studies/runner/ExitCode.hpp"
#include "studies/runner/InterruptFlag.hpp"
#include "studies/runner/OrphanedTemporaries.hpp"
#include "studies/runner/RunCache.hpp"

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

// The normal speeds of the pair impacts over the fields' phase window and pooled cycles (from
// the averager's first pooled cycle, known once the layer is steady, to its last whole
// cycle), for the momentum-transfer study's binary-impact estimate (docs/studies.md).
class PooledPairImpacts : public SnapshotObserver {
 public:
  PooledPairImpacts(const PhaseAverager& averager, double frequency)
      : histogram(bins(averager.config(), frequency)), averager_(averager), frequency_(frequency) {}
  void observe(const Snapshot&) override {
    const int first = averager_.firstPooledCycle();
    if (first >= 0) histogram.startAt(first / frequency_);
  }
  PairImpactHistogram histogram;

 private:
  static PairImpactBins bins(const PhaseAveragerConfig& c, double frequency) {
    PairImpactBins b;
    b.speed_max = 2.0;  // m/s; 5 mm/s bins resolve the wet law's onset at ~0.07 m/s
    b.speed_bins = 400;
    b.period = c.cycles_per_window / frequency;
    b.phase_bins = c.samples_per_cycle * c.cycles_per_window;
    b.start_time = 1e300;  // until the layer is steady
    b.end_time = c.total_cycles / frequency;
    return b;
  }
  const PhaseAverager& averager_;
  double frequency_;
};

// What a checkpoint may only be continued by: the same resolved scene, the same outputs and
// the same build (another build need not give the same bits).
std::string runIdentity(const Scene& scene, const SimulateOptions& opt) {
  return fmt::format(
      "{}\nrun_file={} fields={} fields_period={} fields_blocks={} state_fields={}\nbuild={}\n",
      sceneToToml(scene), !opt.no_output, !opt.fields.empty(), opt.fields_period, opt.fields_blocks,
      opt.state_fields, buildIdentity());
}

double processCpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

double totalEnergy(const Observables& o) {
  return o.kinetic_energy + o.rotational_energy + o.potential_energy;
}

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// One `granwave simulate`: the engine, its observers and, with --checkpoint-every, the
// checkpoints that let the same command continue a killed run.
class SimulationRun {
 public:
  explicit SimulationRun(const SimulateOptions& opt)
      : opt_(opt),
        scene_(parseSceneFile(opt.scene_path, opt.overrides)),
        config_(engineConfig(scene_)),
        out_(opt.output.empty() ? std::filesystem::path(opt.scene_path).stem().string() + ".h5"
                                : opt.output),
        progress_(scene_.run.duration) {
    refuseClashingFiles();
    if (!opt.fields.empty()) {
      averager_ = std::make_unique<PhaseAverager>(
          phaseAveragerConfig(scene_, opt.fields_period, opt.fields_blocks, -1));
      patterns_ =
          std::make_unique<PatternSampler>(PatternSamplerConfig{scene_.run.phases_per_cycle});
      accumulating_.emplace_back("phase_averager", averager_.get());
      accumulating_.emplace_back("patterns", patterns_.get());
      surface_ = std::make_unique<SurfaceRecorder>(surfaceRecorderConfig(scene_));
      accumulating_.emplace_back("surface", surface_.get());
      impacts_ = std::make_unique<PooledPairImpacts>(*averager_, scene_.drive.frequency);
      accumulating_.emplace_back("pair_impacts", &impacts_->histogram);
    }
    if (!opt.fields.empty() && opt.state_fields) {
      states_ = std::make_unique<StatePhaseAverager>(averager_->config());
      accumulating_.emplace_back("state_averager", states_.get());
    }
  }

  // Opens (or continues from the checkpoint) the engine and the run file.
  void start(const std::string& command_line) {
    if (opt_.checkpoint_every > 0) {
      checkpoint_ = std::make_unique<RunCheckpoint>(out_, runIdentity(scene_, opt_));
      removeOrphanedTemporaries(out_);
      if (!opt_.fields.empty()) removeOrphanedTemporaries(opt_.fields);
      if (checkpoint_->exists()) {
        loaded_ = checkpoint_->load(accumulating_);
        resumed_ = true;
      }
    } else if (std::filesystem::exists(out_ + ".checkpoint")) {
      fmt::print(stderr,
                 "granwave: warning: {}.checkpoint is not used without --checkpoint-every; "
                 "this run starts afresh\n",
                 out_);
    }
    const BoxInfo box{scene_.container.width, scene_.container.height, scene_.particles.diameter,
                      scene_.container.periodic_x, scene_.container.periodic_z};
    if (resumed_) {
      continueFromCheckpoint(box);
    } else {
      sim_ = std::make_unique<EdSimulation>(config_, initialCondition(scene_, config_));
      if (!opt_.no_output)
        writer_ = std::make_unique<H5mdWriter>(
            out_, sceneToToml(scene_), RunProvenance{kVersion, command_line, scene_.run.seed, ""},
            box, scene_.run.trajectory_stride);
    }
    if (writer_) sim_->addObserver(writer_.get());
    sim_->addObserver(&com_);
    if (averager_) {
      sim_->addObserver(averager_.get());
      sim_->addObserver(patterns_.get());
      sim_->addObserver(surface_.get());
      sim_->addObserver(impacts_.get());  // after the averager: its first pooled cycle
      sim_->setPairImpactObserver(&impacts_->histogram);
    }
    if (states_) sim_->addObserver(states_.get());
    if (!opt_.quiet) sim_->addObserver(&progress_);
    initial_energy_ = resumed_ ? loaded_.ledger.initial_energy : totalEnergy(sim_->snapshot().obs);
  }

  // Runs to the end or to an interrupt, saving checkpoints on the way.
  RunStatus run() {
    const auto& interrupt = installInterruptFlag();
    t0_ = std::chrono::steady_clock::now();
    cpu0_ = processCpuSeconds();
    auto last_checkpoint = t0_;
    // A save costs about a copy of the run file (docs/performance.md); the interval grows so
    // that saving never takes more than 1/20 of the wall time however large the file gets.
    double last_save = 0;
    const auto due = [&] {
      return checkpoint_ &&
             secondsSince(last_checkpoint) >= std::max(opt_.checkpoint_every, 20 * last_save);
    };
    RunStatus status;
    while (true) {
      try {
        status = sim_->run(&interrupt, due);
      } catch (const std::exception& e) {
        // The engine's breakdowns (collapse, stall) repeat from any checkpoint: they are the
        // run's result, and a checkpoint would only make the next attempt fail again later.
        // A file that could not be written is not: its checkpoint stays for the next try.
        if (checkpoint_ && !isOutsideFailure(e)) checkpoint_->remove();
        throw;
      }
      if (!status.paused) break;
      const auto started = std::chrono::steady_clock::now();
      saveCheckpoint();
      last_save = secondsSince(started);
      last_checkpoint = std::chrono::steady_clock::now();
    }
    // Little is lost on Ctrl-C: the same command continues from here, or, if the interrupt
    // came between two records, from the last checkpoint (a state between records cannot be
    // continued exactly).
    if (status.interrupted && status.at_record && checkpoint_) saveCheckpoint();
    return status;
  }

  // Writes the outputs and the summary; returns the exit code. The checkpoint goes once the
  // outputs are written, or when their analysis fails in a way that would only repeat.
  int finish(const RunStatus& status) {
    if (!checkpoint_ || !status.completed) return writeOutputs(status);
    int code = 0;
    try {
      code = writeOutputs(status);
    } catch (const std::exception& e) {
      if (!isOutsideFailure(e)) removeCheckpoint();
      throw;
    }
    removeCheckpoint();
    return code;
  }

 private:
  // Before any work: no output over the scene, a device or another output (files/).
  void refuseClashingFiles() const {
    std::vector<files::NamedPath> outputs;
    if (!opt_.no_output) outputs.push_back({"run file", out_});
    if (!opt_.no_output && opt_.checkpoint_every > 0)
      outputs.push_back({"checkpoint", out_ + ".checkpoint"});
    if (!opt_.fields.empty()) {
      outputs.push_back({"fields file", opt_.fields});
      outputs.push_back({"fields sidecar", xdmfSidecarPath(opt_.fields)});
    }
    files::requireDistinct({{"scene", opt_.scene_path}}, outputs);
  }

  void continueFromCheckpoint(const BoxInfo& box) {
    const std::string remedy = fmt::format("; remove {} and {}.checkpoint-*.h5md to start afresh",
                                           checkpoint_->statePath(), out_);
    try {
      sim_ = std::make_unique<EdSimulation>(config_, loaded_.engine);
    } catch (const std::exception& e) {
      throw CheckpointError(fmt::format("{}: its engine state cannot be continued ({}){}",
                                        checkpoint_->statePath(), e.what(), remedy));
    }
    if (!opt_.no_output) {
      try {
        writer_ =
            std::make_unique<H5mdWriter>(out_, loaded_.run_copy, box, scene_.run.trajectory_stride);
      } catch (const std::exception& e) {
        throw CheckpointError(
            fmt::format("{}: the run file saved with checkpoint {} cannot be "
                        "continued ({}){}",
                        loaded_.run_copy, loaded_.ledger.checkpoints, e.what(), remedy));
      }
    }
    fmt::print(stderr, "granwave: continuing from {} at t = {:.4f} s (checkpoint {})\n",
               checkpoint_->statePath(), sim_->now(), loaded_.ledger.checkpoints);
  }

  void saveCheckpoint() {
    const auto started = std::chrono::steady_clock::now();
    CheckpointLedger ledger = loaded_.ledger;
    ledger.initial_energy = initial_energy_;
    ledger.wall_seconds += secondsSince(t0_);
    ledger.cpu_seconds += processCpuSeconds() - cpu0_;
    loaded_.ledger.checkpoints = checkpoint_->save(*sim_, writer_.get(), accumulating_, ledger);
    ++checkpoints_written_;
    checkpoint_wall_ += secondsSince(started);
  }

  // Also the partial run file of an earlier Ctrl-C, which the finished run supersedes.
  void removeCheckpoint() {
    checkpoint_->remove();
    std::error_code ec;
    std::filesystem::remove(out_ + ".interrupted", ec);
  }

  int writeOutputs(const RunStatus& status) {
    progress_.finish();
    const Snapshot last = sim_->snapshot();
    RunSummaryInput in;
    in.scene = &scene_;
    in.scene_name = opt_.scene_path;
    in.final_obs = last.obs;
    in.simulated = status.time;
    in.wall = loaded_.ledger.wall_seconds + secondsSince(t0_);
    in.tc = config_.tc;
    in.sleep_alarm_time = sim_->sleepAlarmTime();
    in.completed = status.completed;
    in.com_height = std::move(com_.height);
    in.initial_energy = initial_energy_;
    in.checkpoints = checkpoints_written_;
    in.checkpoint_wall = checkpoint_wall_;
    in.energy_balance_error = std::abs(totalEnergy(last.obs) - in.initial_energy -
                                       last.obs.wall_work + last.obs.dissipated_energy);
    // The fields are analysed before the run file is published: a run whose --fields step
    // fails leaves neither file (the study would otherwise hold half a run).
    std::optional<FieldsAnalysis> fields;
    if (averager_ && status.completed) fields = analyseLiveFields(in);
    if (writer_) {
      if (impacts_) writer_->writePairImpacts(impacts_->histogram);
      const std::string stored = formatRunSummary(in, false);
      if (status.completed) {
        writer_->finish(true, stored);
      } else {
        writer_->finish(false, stored, out_ + ".interrupted");
      }
    }
    fmt::print("{}", formatRunSummary(in));
    if (!status.completed) {
      fmt::print(
          stderr, "granwave: interrupted at t = {:.4f} s; partial run saved as {}{}\n", status.time,
          opt_.no_output ? std::string("(nothing: --no-output)") : out_ + ".interrupted",
          checkpoint_ ? "; the same command continues from " + checkpoint_->statePath() : "");
      return kExitInterrupted;
    }
    if (writer_) fmt::print("output          {}\n", out_);
    if (fields) {
      try {
        writeFieldsFile(opt_.fields, *fields);
      } catch (...) {
        std::error_code ec;
        if (writer_) std::filesystem::remove(out_, ec);
        throw;
      }
      fmt::print("{}", formatFieldsSummary(*fields));
      fmt::print("fields output   {} (+ {})\n", opt_.fields, xdmfSidecarPath(opt_.fields));
    }
    return kExitSuccess;
  }

  FieldsAnalysis analyseLiveFields(const RunSummaryInput& in) const {
    PeriodResult period;
    int discarded = 0;
    const int layer_period = summarisePeriod(in, period, discarded) ? period.period : 0;
    FieldsAnalysis a = analyseFields(*averager_, fieldsContext(scene_, "live: " + opt_.scene_path,
                                                               sceneToToml(scene_), layer_period));
    summarisePeriodDoubling(in, a.context.period_doubling);
    if (states_) addStateFields(a, *states_);
    a.patterns = classifyPatterns(*patterns_, scene_.container.width, scene_.container.height,
                                  scene_.particles.diameter, scene_.container.periodic_x);
    a.surface = surfaceWaves(*surface_, *averager_);
    return a;
  }

  const SimulateOptions& opt_;
  const Scene scene_;
  const EngineConfig config_;
  const std::string out_;
  // Observers that accumulate over the run; a checkpoint saves them by these names.
  CenterOfMassSeries com_;
  std::unique_ptr<PhaseAverager> averager_;
  std::unique_ptr<PatternSampler> patterns_;
  std::unique_ptr<SurfaceRecorder> surface_;
  std::unique_ptr<StatePhaseAverager> states_;
  std::unique_ptr<PooledPairImpacts> impacts_;
  NamedCheckpointables accumulating_{{"center_of_mass", &com_}};
  ProgressReporter progress_;

  std::unique_ptr<RunCheckpoint> checkpoint_;
  LoadedCheckpoint loaded_;
  bool resumed_ = false;
  std::unique_ptr<EdSimulation> sim_;
  std::unique_ptr<H5mdWriter> writer_;
  double initial_energy_ = 0;
  std::chrono::steady_clock::time_point t0_;
  double cpu0_ = 0;
  int checkpoints_written_ = 0;
  double checkpoint_wall_ = 0;
};

}  // namespace

void addSimulateCommand(CLI::App& app, SimulateOptions& opt) {
  CLI::App* cmd = app.add_subcommand("simulate", "Run the event-driven particle engine on a scene");
  cmd->add_option("scene", opt.scene_path, "Scene file (TOML, SI units; see docs/scenes.md)")
      ->required()
      ->check(regularInputFile());
  cmd->add_option("-o,--output", opt.output, "Output run file (H5MD); default <scene>.h5");
  cmd->add_option("--set", opt.overrides,
                  "Override a scene key: section.key=value (repeatable; default: none)")
      ->take_all()
      ->allow_extra_args(false);
  cmd->add_flag("-q,--quiet", opt.quiet, "No progress line on stderr");
  cmd->add_flag("--no-output", opt.no_output, "Do not write a run file (summary only)");
  cmd->add_option("--fields", opt.fields,
                  "Also write phase-averaged fields, computed live (HDF5 + .xdmf; default: "
                  "none)");
  cmd->add_option("--fields-period", opt.fields_period, "Cycles per phase window for --fields")
      ->check(CLI::Range(1, 4))
      ->capture_default_str();
  cmd->add_option("--fields-blocks", opt.fields_blocks, "Blocks of cycles for --fields")
      ->check(CLI::Range(2, 50))
      ->capture_default_str();
  cmd->add_flag("--state-fields", opt.state_fields,
                "With --fields: also average the fields over the period-1 and the period-2 "
                "windows of the layer separately (/states; about twice the memory)");
  cmd->add_option("--checkpoint-every", opt.checkpoint_every,
                  "Save a checkpoint every this many seconds of wall time (and on Ctrl-C); "
                  "the same command then continues a killed run from it (default: none)")
      ->check(CLI::PositiveNumber)
      ->check(finiteNumber());
}

int runSimulate(const SimulateOptions& opt, const std::string& command_line) {
  // From the start, not only once the engine runs: a SIGTERM while the run file is being
  // created (a study killed just after launching this run) would otherwise leave it behind.
  installInterruptFlag();
  SimulationRun run(opt);
  run.start(command_line);
  return run.finish(run.run());
}

}  // namespace granwave
