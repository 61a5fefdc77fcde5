#pragma once
// What a study asks to be run (one scene through the particle engine or the hydro solver),
// and what came of it. Studies plan requests; the RunScheduler runs or reuses them.
#include <string>

#include "scene/Scene.hpp"

namespace granwave {

enum class RunKind { Particles, Hydro };

struct RunRequest {
  RunKind kind = RunKind::Particles;
  std::string label;  // unique within a study: progress lines, tables, lookup
  Scene scene;        // fully resolved
  // Particles: live phase-averaged fields (driven scenes) with this window (cycles) and
  // blocks.
  bool fields = true;
  int window_cycles = 2;
  int blocks = 5;
};

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
  std::string logPath() const { return stem + ".log"; }
  std::string recordPath() const { return stem + ".done"; }
};

}  // namespace granwave
