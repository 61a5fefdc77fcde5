#include "studies/cli/FieldsCommand.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "coarse_grain/FieldsFile.hpp"
#include "coarse_grain/PeriodDetector.hpp"
#include "coarse_grain/SteadyStateDetector.hpp"
#include "files/OutputPath.hpp"
#include "particles/H5mdReader.hpp"
#include "scene/SceneParser.hpp"
#include "studies/cli/FieldsSetup.hpp"
#include "studies/cli/OptionChecks.hpp"
#include "studies/cli/RunSummary.hpp"

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
  const int period_choice = parseChoice(opt.period, "--period", 1, 4);
  const int discard_choice = parseChoice(opt.discard, "--discard", 0, 1000000);
  std::string out = opt.output;
  if (out.empty())
    out = std::filesystem::path(opt.run_path).replace_extension(".fields.h5").string();
  files::requireDistinct({{"run file", opt.run_path}},
                         {{"fields file", out}, {"fields sidecar", xdmfSidecarPath(out)}});
  const H5mdReader run(opt.run_path);
  const Scene scene = parseSceneString(run.sceneToml(), {}, opt.run_path + ":/parameters/scene");
  if (scene.drive.frequency <= 0)
    throw std::runtime_error(opt.run_path + ": phase-averaged fields need a driven scene");
  if (run.frameCount() != run.recordCount())
    throw std::runtime_error(fmt::format(
        "{}: fields need a trajectory frame at every record ({} frames, {} records); simulate "
        "with run.trajectory_stride = 1, or use simulate --fields",
        opt.run_path, run.frameCount(), run.recordCount()));
  if (!run.completed())
    fmt::print(stderr, "granwave: {} is an interrupted run; using what it holds\n", opt.run_path);

  const int M = scene.run.phases_per_cycle;
  const std::vector<double> com = run.observable("center_of_mass_height").value;
  int discard = discard_choice;
  if (discard < 0) {
    discard = steadyCycles(com, M);
    if (discard < 0)
      throw std::runtime_error(opt.run_path +
                               ": the layer never became steady (run longer, or give --discard)");
  }
  // The run's period by the rule `simulate` uses (runPeriod), not over this command's
  // window, so a run has one period.
  int layer_period = 0;
  PeriodDoublingSeries period_doubling;
  try {
    const RunPeriod rp = runPeriod(com, M);
    layer_period = rp.result.period;
    period_doubling = periodDoublingSeries(com, M, rp.discarded);
  } catch (const std::invalid_argument&) {
  }
  int P = period_choice;
  if (P < 0) P = layer_period >= 1 && layer_period <= 4 ? layer_period : 2;

  PhaseAveragerConfig cfg = phaseAveragerConfig(scene, P, opt.blocks, discard);
  cfg.total_cycles = static_cast<int>(run.recordCount() / M);
  PhaseAverager averager(cfg);
  std::optional<StatePhaseAverager> states;
  if (opt.state_fields) states.emplace(cfg);
  PatternSampler patterns({M});
  SurfaceRecorder surface(surfaceRecorderConfig(scene));
  for (std::size_t i = 0; i < run.frameCount(); ++i) {
    const Snapshot s = run.frame(i);
    averager.observe(s);
    if (states) states->observe(s);
    patterns.observe(s);
    surface.observe(s);
  }

  FrontOptions fronts;
  fronts.threshold = opt.front_threshold;
  FieldsAnalysis a = analyseFields(
      averager, fieldsContext(scene, opt.run_path, run.sceneToml(), layer_period), fronts);
  a.context.period_doubling = period_doubling;
  if (states) addStateFields(a, *states);
  a.patterns = classifyPatterns(patterns, scene.container.width, scene.container.height,
                                scene.particles.diameter, scene.container.periodic_x);
  a.surface = surfaceWaves(surface, averager);
  writeFieldsFile(out, a);
  fmt::print("run             {}\n", opt.run_path);
  if (layer_period > 0) fmt::print("layer period    {}T (centre of mass)\n", layer_period);
  if (!period_doubling.period2.empty()) fmt::print("{}", formatPeriodDoubling(period_doubling));
  fmt::print("{}", formatFieldsSummary(a));
  fmt::print("output          {} (+ {})\n", out, xdmfSidecarPath(out));
  return 0;
}

}  // namespace granwave
