#pragma once
// `granwave simulate SCENE.toml [-o RUN.h5] [--set section.key=value]...`: runs the ED
// engine on a scene, writes the H5MD run atomically and prints a summary on stdout. With
// --checkpoint-every S it saves a checkpoint every S seconds of wall time (and on Ctrl-C),
// and the same command continues a killed run from it (studies/RunCheckpoint.hpp).
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace granwave {

struct SimulateOptions {
  std::string scene_path;
  std::string output;  // default: <scene stem>.h5 in the working directory
  std::vector<std::string> overrides;
  bool quiet = false;      // no progress line
  bool no_output = false;  // run and summarise only
  std::string fields;      // live phase-averaged fields file (empty = none)
  int fields_period = 2;   // cycles per phase window
  int fields_blocks = 5;
  bool state_fields = false;    // also average the fields per layer state (/states)
  double checkpoint_every = 0;  // s of wall time between checkpoints; 0 = none
};

void addSimulateCommand(CLI::App& app, SimulateOptions& options);
// Returns the process exit code; throws on errors (main reports them in one line).
int runSimulate(const SimulateOptions& options, const std::string& command_line);

}  // namespace granwave
