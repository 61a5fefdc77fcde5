#include "studies/hydro_run/Hydro2DRun.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "coarse_grain/SurfaceRecorder.hpp"
#include "hydro/Layer2DStart.hpp"
#include "scene/SceneParser.hpp"
#include "studies/hydro_run/ContinuumSurface.hpp"
#include "studies/hydro_run/HydroModel.hpp"
#include "studies/hydro_run/HydroRun.hpp"

namespace granwave {

int hydroColumns(const Scene& scene) {
  if (scene.hydro.columns > 0) return scene.hydro.columns;
  return std::max(
      1, static_cast<int>(std::lround(scene.container.width / (4 * scene.particles.diameter))));
}

hydro::Hydro2DRunOptions hydro2DRunOptions(const Scene& scene, const SceneDerived& dv) {
  const hydro::HydroRunOptions one = hydroRunOptions(scene, dv);
  hydro::Hydro2DRunOptions o;
  o.samples_per_cycle = one.samples_per_cycle;
  o.cycles = one.max_cycles;
  o.window_cycles = 2;
  o.rtol = one.cvode.rtol;
  o.atol_scale = one.atol_scale;
  o.initial_theta = one.initial_theta;
  o.spread = one.start == hydro::HydroRunOptions::Start::Spread;
  o.remap_share = scene.hydro.remap_share;
  return o;
}

Hydro2DRunContent hydro2DRunContent(const Scene& scene, const hydro::GranularHydro2D& op,
                                    const hydro::Hydro2DResult& r,
                                    const hydro::Hydro2DRunOptions& o) {
  const double mass = derive(scene).mass;
  Hydro2DRunContent c;
  c.columns = static_cast<std::size_t>(op.columns());
  c.cells = static_cast<std::size_t>(op.cells());
  c.width = op.columnGrid().width;
  c.periodic = op.periodic();
  for (const hydro::Hydro2DPhase& ph : r.window) {
    c.time.push_back(ph.time);
    c.plate_height.push_back(ph.plate_height);
    c.plate_velocity.push_back(ph.plate_velocity);
    c.center_of_mass_height.push_back(ph.center_of_mass_height + ph.plate_height);
    c.node_z.insert(c.node_z.end(), ph.node_z.begin(), ph.node_z.end());
    c.area_fraction.insert(c.area_fraction.end(), ph.area_fraction.begin(), ph.area_fraction.end());
    for (double th : ph.theta) c.temperature.push_back(mass * th);  // T = m theta
    c.velocity_x.insert(c.velocity_x.end(), ph.velocity_x.begin(), ph.velocity_x.end());
    c.velocity_z.insert(c.velocity_z.end(), ph.velocity_z.begin(), ph.velocity_z.end());
    c.pressure.insert(c.pressure.end(), ph.pressure.begin(), ph.pressure.end());
    const hydro::PhaseBudget& b = ph.budget;  // J of the box already (the layer's columns x dx)
    if (op.hasEnergyBudget())
      c.budget.addPhase(1.0, b.plate_work, b.collisional_loss, b.friction_loss, b.wall_loss,
                        b.side_wall_loss, b.energy_change);
  }
  c.com_per_phase = r.com_per_phase;
  c.samples_per_cycle = o.samples_per_cycle;
  c.rtol = o.rtol;
  c.cpu_seconds = r.cpu_seconds;
  c.mass_drift = r.mass_drift;
  c.cycles = r.cycles;
  c.steps = r.stats.steps;
  c.rhs_evals = r.stats.rhs_evals + r.stats.lin_rhs_evals;
  c.linear_iterations = r.stats.lin_iters;
  c.preconditioner_jacobians = r.preconditioner_jacobians;
  c.remaps = r.remaps;
  c.remap_heat = r.remap_heat;
  c.scene_toml = sceneToToml(scene);
  return c;
}

std::unique_ptr<hydro::GranularHydro2D> hydro2DOperator(const Scene& scene,
                                                        const SceneDerived& dv) {
  hydro::ConstitutiveModel model = constitutiveModel(scene, dv);
  model.side_wall_width = 0;  // side walls are explicit in 2D (container.periodic_x = false)
  const hydro::HydroColumns grid{hydroColumns(scene), scene.container.width,
                                 scene.container.periodic_x};
  const hydro::HydroGeometry geometry = hydroGeometry(scene, dv);
  return std::make_unique<hydro::GranularHydro2D>(
      geometry, grid, model,
      hydro::perturbedCellMasses(grid.columns, geometry.cells,
                                 scene.particles.count * dv.mass / scene.container.width,
                                 scene.hydro.perturbation, scene.run.seed),
      hydroRegularisation(scene), scene.hydro.energy_budget);
}

Hydro2DRunContent runHydro2DScene(const Scene& scene, const std::string& scene_name,
                                  std::FILE* progress) {
  requireHydroScene(scene, scene_name);
  const SceneDerived dv = derive(scene);
  const std::unique_ptr<hydro::GranularHydro2D> op = hydro2DOperator(scene, dv);
  const hydro::Hydro2DRunOptions o = hydro2DRunOptions(scene, dv);
  if (progress)
    fmt::print(progress, "  integrating {} cycles ({} columns x {} cells)...\n", o.cycles,
               op->columns(), op->cells());
  // The surface at every phase, measured as the particles' (ContinuumSurface.hpp); its
  // spectrum over the run's second half, as the waves grow from the seeded perturbation.
  const ContinuumColumns grid{op->columns(), op->cells(), scene.container.width,
                              scene.container.periodic_x, scene.particles.diameter};
  SurfaceRecorderConfig rc;
  rc.records_per_cycle = o.samples_per_cycle;
  rc.keep_cycles = o.cycles - o.cycles / 2;
  rc.width = grid.width;
  rc.diameter = grid.diameter;
  rc.periodic_x = grid.periodic_x;
  SurfaceRecorder surface(rc);
  hydro::HydroSimulation2D sim(*op, o);
  const hydro::Hydro2DResult result =
      sim.run([&](const hydro::Hydro2DPhase& ph, int cycle, int phase) {
        // Only the second half is analysed: the first is not measured at all.
        if (cycle >= o.cycles / 2)
          surface.record(cycle, phase, continuumSurface(ph, grid, rc.surface));
      });
  Hydro2DRunContent content = hydro2DRunContent(scene, *op, result, o);
  const SurfaceSeries series = surface.series(o.cycles / 2);
  SurfaceSpectrumOptions so;
  so.window_cycles = surfaceWindowCycles(series.cycles, so);
  content.surface = analyseSurfaceWaves(series, so);
  return content;
}

}  // namespace granwave
