#include "studies/hydro_run/HydroRun.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "scene/SceneParser.hpp"
#include "studies/hydro_run/HydroModel.hpp"
#include "studies/hydro_run/LabFrame.hpp"

namespace granwave {

namespace {

// The plate-frame fields of every phase of the window, as the file holds them.
void plateFrameFields(const hydro::HydroResult& r, double mass, HydroRunContent& c) {
  for (const auto& ph : r.window) {
    c.plate_z.insert(c.plate_z.end(), ph.z.begin(), ph.z.end());  // Lagrangian: moves per phase
    c.number_density.insert(c.number_density.end(), ph.n.begin(), ph.n.end());
    c.velocity_z.insert(c.velocity_z.end(), ph.u.begin(), ph.u.end());
    for (double th : ph.theta) c.temperature.push_back(mass * th);
    c.area_fraction.insert(c.area_fraction.end(), ph.area_fraction.begin(), ph.area_fraction.end());
    c.pressure.insert(c.pressure.end(), ph.pressure.begin(), ph.pressure.end());
  }
}

}  // namespace

HydroRunContent hydroRunContent(const Scene& scene, const SceneDerived& dv,
                                const hydro::HydroResult& r, const hydro::HydroRunOptions& ro) {
  HydroRunContent c;
  c.cells = static_cast<std::size_t>(scene.hydro.cells);
  plateFrameFields(r, dv.mass, c);
  c.lab = labFrameProfiles(scene, dv, r, ro.samples_per_cycle);
  c.rtol = ro.cvode.rtol;
  c.cycles = r.cycles;
  c.period = r.period;
  c.periodic = r.periodic;
  c.regime = hydro::regimeName(r.regime);
  c.cpu_seconds = r.cpu_seconds;
  c.steps = r.stats.steps;
  c.rhs_evals = r.stats.rhs_evals + r.stats.lin_rhs_evals;
  c.jacobian_evals = r.stats.jac_evals;
  c.error_test_failures = r.stats.err_test_fails;
  c.nonlinear_failures = r.stats.nonlin_conv_fails;
  c.scene_toml = sceneToToml(scene);
  return c;
}

void requireHydroScene(const Scene& scene, const std::string& scene_name) {
  if (scene.drive.frequency <= 0)
    throw std::runtime_error(scene_name +
                             ": granwave hydro needs a driven scene (drive.frequency > 0)");
  if (scene.container.periodic_z)
    throw std::runtime_error(
        scene_name + ": granwave hydro needs bottom and lid (container.periodic_z = false)");
}

HydroRunContent runHydroScene(const Scene& scene, const std::string& scene_name,
                              std::FILE* progress) {
  requireHydroScene(scene, scene_name);
  const SceneDerived dv = derive(scene);
  const hydro::GranularHydro1D pde(hydroGeometry(scene, dv), constitutiveModel(scene, dv),
                                   scene.particles.count * dv.mass / scene.container.width,
                                   hydroRegularisation(scene));
  const hydro::HydroRunOptions ro = hydroRunOptions(scene, dv);
  hydro::HydroSimulation sim(pde, ro);
  if (progress)
    fmt::print(progress, "  integrating up to {} cycles ({} cells)...\n", ro.max_cycles,
               scene.hydro.cells);
  return hydroRunContent(scene, dv, sim.run(), ro);
}

}  // namespace granwave
