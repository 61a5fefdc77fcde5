#include "studies/particle_run/RunFileFields.hpp"

#include <fmt/format.h>

#include <optional>
#include <stdexcept>

#include "coarse_grain/PeriodDetector.hpp"
#include "coarse_grain/SteadyStateDetector.hpp"
#include "particles/H5mdReader.hpp"
#include "scene/SceneParser.hpp"
#include "studies/particle_run/FieldsSetup.hpp"

namespace granwave {

namespace {

// The run's scene, refused unless it is driven and every record has its trajectory frame.
Scene replayableScene(const H5mdReader& run, const std::string& path) {
  const Scene scene = parseSceneString(run.sceneToml(), {}, path + ":/parameters/scene");
  if (scene.drive.frequency <= 0)
    throw std::runtime_error(path + ": phase-averaged fields need a driven scene");
  if (run.frameCount() != run.recordCount())
    throw std::runtime_error(fmt::format(
        "{}: fields need a trajectory frame at every record ({} frames, {} records); simulate "
        "with run.trajectory_stride = 1, or use simulate --fields",
        path, run.frameCount(), run.recordCount()));
  if (!run.completed())
    fmt::print(stderr, "granwave: {} is an interrupted run; using what it holds\n", path);
  return scene;
}

}  // namespace

FieldsAnalysis fieldsOfRunFile(const std::string& path, const RunFileFieldsOptions& opt) {
  const H5mdReader run(path);
  const Scene scene = replayableScene(run, path);
  const int M = scene.run.phases_per_cycle;
  const std::vector<double> com = run.observable("center_of_mass_height").value;
  int discard = opt.discard;
  if (discard < 0) {
    discard = steadyCycles(com, M);
    if (discard < 0)
      throw std::runtime_error(path +
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
  int P = opt.period;
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
  FieldsAnalysis a =
      analyseFields(averager, fieldsContext(scene, path, run.sceneToml(), layer_period), fronts);
  a.context.period_doubling = period_doubling;
  if (states) addStateFields(a, *states);
  a.patterns = classifyPatterns(patterns, scene.container.width, scene.container.height,
                                scene.particles.diameter, scene.container.periodic_x);
  a.surface = surfaceWaves(surface, averager);
  return a;
}

}  // namespace granwave
