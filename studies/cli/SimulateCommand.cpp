#include "studies/cli/SimulateCommand.hpp"

#include <CLI/CLI.hpp>

#include "studies/cli/OptionChecks.hpp"
#include "studies/cli/Version.hpp"

namespace granwave {

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
  CLI::Option* fields =
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
  cmd->add_flag("--fields-without-cells{false}", opt.fields_cells,
                "With --fields: leave out the x-z cells and their XDMF sidecar, keeping the "
                "profiles, phases, fronts and states (what the studies read; a tenth of the "
                "size; default: cells written)")
      ->needs(fields);
  cmd->add_option("--checkpoint-every", opt.checkpoint_every,
                  "Save a checkpoint every this many seconds of wall time (and on Ctrl-C); "
                  "the same command then continues a killed run from it (default: none)")
      ->check(numberAbove(0, false))
      ->check(finiteNumber());
}

int runSimulate(const SimulateOptions& opt, const std::string& command_line) {
  return runParticles(opt, command_line, kVersion);
}

}  // namespace granwave
