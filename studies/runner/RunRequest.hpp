#pragma once
// What a study asks to be run (one scene through the particle engine or the hydro solver),
// and what came of it. Studies plan requests; the RunScheduler runs or reuses them.
#include <string>
#include <vector>

#include "scene/Scene.hpp"

namespace granwave {

// Lammps: the soft-sphere DEM alternative (studies/lammps/paper-scene.lmp), run by the
// program and arguments below; its output is <stem>.com.txt.
enum class RunKind { Particles, Hydro, Lammps };

// "particles", "hydro" or "lammps": the kind's name in the run cache's file names and keys.
inline const char* runKindName(RunKind kind) {
  return kind == RunKind::Particles ? "particles" : kind == RunKind::Hydro ? "hydro" : "lammps";
}

struct RunRequest {
  RunKind kind = RunKind::Particles;
  std::string label;  // unique within a study: progress lines, tables, lookup
  Scene scene;        // fully resolved
  // Particles: live phase-averaged fields (driven scenes) with this window (cycles) and
  // blocks.
  bool fields = true;
  int window_cycles = 2;
  int blocks = 5;
  // Also the fields of the period-1 and the period-2 windows (simulate --state-fields): about
  // twice the fields' memory and file size, so only for runs whose states a study reads.
  bool state_fields = false;
  // Lammps: the executable, the deck's text (part of the cache key) and its -var arguments
  // (the scheduler adds -in, -log and the output file).
  std::string program, deck_path, deck_text;
  std::vector<std::string> variables;  // name, value, name, value, ...
  // How the progress line names a failure of this run; empty: "FAILED". A study that runs a
  // case to see whether it fails (the wave-fronts study's failure map) says so here, so that
  // a reader of the progress lines does not take the intended result for a fault.
  std::string failure_note;
};

inline RunRequest runRequest(RunKind kind, std::string label, Scene scene) {
  RunRequest q;
  q.kind = kind;
  q.label = std::move(label);
  q.scene = std::move(scene);
  return q;
}

struct RunRecord {
  RunRequest request;
  std::string stem;  // OUTDIR/runs/<kind>-<hash>: every file of the run starts with it
  bool ok = false;
  bool reused = false;  // found complete in the cache
  int exit_code = 0;
  std::string message;       // the run's last log line when it failed
  double wall = 0, cpu = 0;  // s, as measured when the run was made

  std::string scenePath() const { return stem + ".toml"; }
  std::string runPath() const { return stem + ".h5"; }
  std::string fieldsPath() const { return stem + ".fields.h5"; }
  std::string hydroPath() const { return stem + ".hydro.h5"; }
  std::string lammpsPath() const { return stem + ".com.txt"; }
  // The log of one attempt at the run (stdout and stderr of its process): named per attempt,
  // so that no other study sharing the cache removes or rewrites it while it is read.
  std::string attempt;
  std::string logPath() const {
    return attempt.empty() ? stem + ".log" : stem + "." + attempt + ".log";
  }
  std::string recordPath() const { return stem + ".done"; }
};

}  // namespace granwave
