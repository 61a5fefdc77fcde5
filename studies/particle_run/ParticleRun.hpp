#pragma once
// One particle run as `granwave simulate` makes it (docs/commands.md): the engine on a scene
// with its observers (the run file, the live fields, patterns, surface and layer states, the
// centre of mass, the pooled pair impacts, the progress line), checkpoints that let the same
// command continue a killed run bit for bit (studies/run_files/RunCheckpoint.hpp), and at the end
// the outputs and the summary on stdout.
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "coarse_grain/FieldsAnalysis.hpp"
#include "coarse_grain/PatternSampler.hpp"
#include "coarse_grain/PhaseAverager.hpp"
#include "coarse_grain/StatePhaseAverager.hpp"
#include "coarse_grain/SurfaceRecorder.hpp"
#include "particles/EdSimulation.hpp"
#include "particles/H5mdWriter.hpp"
#include "scene/Scene.hpp"
#include "studies/particle_run/ProgressReporter.hpp"
#include "studies/particle_run/RunObservers.hpp"
#include "studies/particle_run/RunSummary.hpp"
#include "studies/run_files/RunCheckpoint.hpp"

namespace granwave {

struct ParticleRunOptions {
  std::string scene_path;
  std::string output;  // default: <scene stem>.h5 in the working directory
  std::vector<std::string> overrides;
  bool quiet = false;      // no progress line
  bool no_output = false;  // run and summarise only
  std::string fields;      // live phase-averaged fields file (empty = none)
  int fields_period = 2;   // cycles per phase window
  int fields_blocks = 5;
  bool state_fields = false;    // also average the fields per layer state (/states)
  bool fields_cells = true;     // the x-z cells and their sidecar (false: profiles etc. only)
  double checkpoint_every = 0;  // s of wall time between checkpoints; 0 = none
};

class ParticleRun {
 public:
  // Parses the scene and refuses outputs that clash with it or each other (files/), before
  // any work.
  explicit ParticleRun(const ParticleRunOptions& options);
  // Opens the engine and the run file, or continues both from the checkpoint.
  void start(const std::string& command_line, const std::string& program_version);
  // Runs to the end or to an interrupt, saving checkpoints on the way.
  RunStatus run();
  // Writes the outputs and the summary; returns the exit code. The checkpoint goes once the
  // outputs are written, or when their analysis fails in a way that would only repeat.
  int finish(const RunStatus& status);

 private:
  void refuseClashingFiles() const;
  void continueFromCheckpoint(const BoxInfo& box);
  void saveCheckpoint();
  void removeCheckpoint();
  int writeOutputs(const RunStatus& status);
  FieldsAnalysis analyseLiveFields(const RunSummaryInput& in) const;

  const ParticleRunOptions& opt_;
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

// The whole command: start, run, finish. Returns the process exit code; throws on errors (the
// program reports them in one line).
int runParticles(const ParticleRunOptions& options, const std::string& command_line,
                 const std::string& program_version);

}  // namespace granwave
