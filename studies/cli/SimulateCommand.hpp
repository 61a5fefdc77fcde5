#pragma once
// `granwave simulate SCENE.toml [-o RUN.h5] [--set section.key=value]...`: runs the ED
// engine on a scene, writes the H5MD run atomically and prints a summary on stdout. With
// --checkpoint-every S it saves a checkpoint every S seconds of wall time (and on Ctrl-C),
// and the same command continues a killed run from it (studies/run_files/RunCheckpoint.hpp).
#include <string>

#include "studies/particle_run/ParticleRun.hpp"

namespace CLI {
class App;
}

namespace granwave {

// The options are those of the particle run (studies/particle_run/ParticleRun.hpp).
using SimulateOptions = ParticleRunOptions;

void addSimulateCommand(CLI::App& app, SimulateOptions& options);
// Returns the process exit code; throws on errors (main reports them in one line).
int runSimulate(const SimulateOptions& options, const std::string& command_line);

}  // namespace granwave
