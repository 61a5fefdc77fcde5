#include "studies/particle_run/ParticleRun.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "coarse_grain/FieldsFile.hpp"
#include "files/OutputPath.hpp"
#include "particles/InitialState.hpp"
#include "scene/SceneParser.hpp"
#include "studies/particle_run/FieldsSetup.hpp"
#include "studies/particle_run/OutsideFailure.hpp"
#include "studies/runner/ExitCode.hpp"
#include "studies/runner/InterruptFlag.hpp"
#include "studies/runner/OrphanedTemporaries.hpp"
#include "studies/runner/RunCache.hpp"

namespace granwave {

namespace {

// What a checkpoint may only be continued by: the same resolved scene, the same outputs and
// the same build (another build need not give the same bits).
std::string runIdentity(const Scene& scene, const ParticleRunOptions& opt) {
  return fmt::format(
      "{}\nrun_file={} fields={} fields_period={} fields_blocks={} state_fields={}{}\nbuild={}\n",
      sceneToToml(scene), !opt.no_output, !opt.fields.empty(), opt.fields_period, opt.fields_blocks,
      opt.state_fields, opt.fields_cells ? "" : " cells=0", buildIdentity());
}

double processCpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

double totalEnergy(const Observables& o) {
  return o.kinetic_energy + o.rotational_energy + o.potential_energy;
}

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

ParticleRun::ParticleRun(const ParticleRunOptions& opt)
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
    patterns_ = std::make_unique<PatternSampler>(PatternSamplerConfig{scene_.run.phases_per_cycle});
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
void ParticleRun::start(const std::string& command_line, const std::string& program_version) {
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
          out_, sceneToToml(scene_),
          RunProvenance{program_version, command_line, scene_.run.seed, ""}, box,
          scene_.run.trajectory_stride);
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
RunStatus ParticleRun::run() {
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
int ParticleRun::finish(const RunStatus& status) {
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

// Before any work: no output over the scene, a device or another output, and no file named
// like one this run makes beside its outputs and removes (files/SideFiles.hpp).
void ParticleRun::refuseClashingFiles() const {
  std::vector<files::NamedPath> outputs;
  const bool checkpointed = opt_.checkpoint_every > 0;
  // A checkpointed run keeps its lock beside the run file even with --no-output.
  if (!opt_.no_output || checkpointed) outputs.push_back({"run file", out_});
  if (!opt_.no_output) outputs.push_back({"partial run file", out_ + ".interrupted", true});
  if (checkpointed) {
    outputs.push_back({"checkpoint", out_ + ".checkpoint", true});
    outputs.push_back({"lock file", out_ + ".lock", true});
    // The longest name a checkpoint copy takes (checkpoint K < 10^7): its temporary must fit.
    if (!opt_.no_output)
      outputs.push_back({"checkpoint copy", out_ + ".checkpoint-9999999.h5md", true});
  }
  if (!opt_.fields.empty()) {
    outputs.push_back({"fields file", opt_.fields});
    outputs.push_back({"fields sidecar", xdmfSidecarPath(opt_.fields)});
  }
  files::requireDistinct({{"scene", opt_.scene_path}}, outputs);
}

void ParticleRun::continueFromCheckpoint(const BoxInfo& box) {
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

void ParticleRun::saveCheckpoint() {
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
void ParticleRun::removeCheckpoint() {
  checkpoint_->remove();
  std::error_code ec;
  std::filesystem::remove(out_ + ".interrupted", ec);
}

int ParticleRun::writeOutputs(const RunStatus& status) {
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
    fmt::print(stderr, "granwave: interrupted at t = {:.4f} s; partial run saved as {}{}\n",
               status.time,
               opt_.no_output ? std::string("(nothing: --no-output)") : out_ + ".interrupted",
               checkpoint_ ? "; the same command continues from " + checkpoint_->statePath() : "");
    return kExitInterrupted;
  }
  if (writer_) fmt::print("output          {}\n", out_);
  if (fields) {
    try {
      writeFieldsFile(opt_.fields, *fields,
                      opt_.fields_cells ? FieldsCells::written : FieldsCells::left_out);
    } catch (...) {
      std::error_code ec;
      if (writer_) std::filesystem::remove(out_, ec);
      throw;
    }
    fmt::print("{}", formatFieldsSummary(*fields));
    if (opt_.fields_cells)
      fmt::print("fields output   {} (+ {})\n", opt_.fields, xdmfSidecarPath(opt_.fields));
    else
      fmt::print("fields output   {} (profiles; cells left out)\n", opt_.fields);
  }
  return kExitSuccess;
}

FieldsAnalysis ParticleRun::analyseLiveFields(const RunSummaryInput& in) const {
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

int runParticles(const ParticleRunOptions& opt, const std::string& command_line,
                 const std::string& program_version) {
  // From the start, not only once the engine runs: a SIGTERM while the run file is being
  // created (a study killed just after launching this run) would otherwise leave it behind.
  installInterruptFlag();
  ParticleRun run(opt);
  run.start(command_line, program_version);
  return run.finish(run.run());
}

}  // namespace granwave
