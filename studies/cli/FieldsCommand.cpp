#include "studies/cli/FieldsCommand.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <stdexcept>

#include "coarse_grain/FieldsFile.hpp"
#include "files/OutputPath.hpp"
#include "studies/cli/OptionChecks.hpp"
#include "studies/particle_run/FieldsSetup.hpp"
#include "studies/particle_run/RunFileFields.hpp"
#include "studies/particle_run/RunSummary.hpp"

namespace granwave {

namespace {
int parseChoice(const std::string& value, const char* option, int lo, int hi) {
  if (value == "auto") return -1;
  try {
    std::size_t used = 0;
    const int v = std::stoi(value, &used);
    if (used == value.size() && v >= lo && v <= hi) return v;
  } catch (const std::exception&) {
  }
  throw CLI::ValidationError(
      option, fmt::format("'{}' is not auto or a whole number in [{}, {}]", value, lo, hi));
}
}  // namespace

void addFieldsCommand(CLI::App& app, FieldsOptions& opt) {
  CLI::App* cmd =
      app.add_subcommand("fields", "Phase-averaged fields, profiles and wave fronts of a run");
  cmd->add_option("run", opt.run_path, "Run file written by granwave simulate (every record)")
      ->required()
      ->check(regularInputFile());
  cmd->add_option("-o,--output", opt.output, "Fields file (HDF5 + .xdmf); default <run>.fields.h5");
  cmd->add_option(
         "--period", opt.period,
         "Cycles per phase window: auto (the layer's period, from its centre of mass) or 1-4")
      ->capture_default_str();
  cmd->add_option("--blocks", opt.blocks, "Independent blocks of cycles for uncertainties")
      ->check(CLI::Range(2, 50))
      ->capture_default_str();
  cmd->add_option("--discard", opt.discard, "Transient cycles to discard: auto or a number")
      ->capture_default_str();
  cmd->add_option("--front-threshold", opt.front_threshold,
                  "T~_g/T0 above which a temperature peak is a front (paper: 0.5)")
      ->check(CLI::Range(0.01, 100.0))
      ->check(finiteNumber())
      ->capture_default_str();
  cmd->add_flag("--state-fields", opt.state_fields,
                "Also average the fields over the period-1 and the period-2 windows of the "
                "layer separately (/states; about twice the memory)");
}

int runFields(const FieldsOptions& opt) {
  RunFileFieldsOptions fields;
  fields.period = parseChoice(opt.period, "--period", 1, 4);
  fields.discard = parseChoice(opt.discard, "--discard", 0, 1000000);
  fields.blocks = opt.blocks;
  fields.front_threshold = opt.front_threshold;
  fields.state_fields = opt.state_fields;
  std::string out = opt.output;
  if (out.empty())
    out = std::filesystem::path(opt.run_path).replace_extension(".fields.h5").string();
  files::requireDistinct({{"run file", opt.run_path}},
                         {{"fields file", out}, {"fields sidecar", xdmfSidecarPath(out)}});
  const FieldsAnalysis a = fieldsOfRunFile(opt.run_path, fields);
  writeFieldsFile(out, a);
  fmt::print("run             {}\n", opt.run_path);
  if (a.context.layer_period > 0)
    fmt::print("layer period    {}T (centre of mass)\n", a.context.layer_period);
  if (!a.context.period_doubling.period2.empty())
    fmt::print("{}", formatPeriodDoubling(a.context.period_doubling));
  fmt::print("{}", formatFieldsSummary(a));
  fmt::print("output          {} (+ {})\n", out, xdmfSidecarPath(out));
  return 0;
}

}  // namespace granwave
