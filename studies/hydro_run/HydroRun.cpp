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
  c.com_history = r.com_per_phase;
  c.phases_per_cycle = ro.samples_per_cycle;
  if (scene.hydro.energy_budget)  // J/m of the continuum's column -> J of the scene's box
    for (const auto& ph : r.window) {
      const hydro::PhaseBudget& b = ph.budget;
      c.budget.addPhase(scene.container.width, b.plate_work, b.collisional_loss, b.friction_loss,
                        b.wall_loss, b.side_wall_loss, b.energy_change);
    }
  c.steps = r.stats.steps;
  c.rhs_evals = r.stats.rhs_evals + r.stats.lin_rhs_evals;
  c.jacobian_evals = r.stats.jac_evals;
  c.error_test_failures = r.stats.err_test_fails;
  c.nonlinear_failures = r.stats.nonlin_conv_fails;
  c.scene_toml = sceneToToml(scene);
  return c;
}

void requireHydroScene(const Scene& scene, const std::string& scene_name) {
  const auto refuse = [&scene_name](const std::string& why) {
    throw SceneError(scene_name + ": granwave hydro needs " + why);
  };
  if (scene.drive.frequency <= 0) refuse("a driven scene (drive.frequency > 0)");
  // Gamma = 0 is a plate at rest: the layer settles, and no front or period exists to find.
  if (!(derive(scene).amplitude > 0))
    refuse("a driven scene (drive.gamma or drive.amplitude > 0; the plate amplitude is 0)");
  if (scene.container.periodic_z) refuse("bottom and lid (container.periodic_z = false)");
  // Walton's law with e_t0 = -1 makes every contact smooth: no spin is exchanged, the
  // rotational temperature has no source and its logarithm runs off to -infinity.
  if (scene.hydro.particles == HydroParticles::Rough && scene.contact.tangential_limit <= -1)
    refuse(
        "contact.tangential_limit > -1 for hydro.particles = \"rough\" (at -1 every contact "
        "is smooth: use hydro.particles = \"smooth\", the same physics)");
}

HydroRunContent runHydroScene(const Scene& scene, const std::string& scene_name,
                              std::FILE* progress, const std::atomic<bool>* interrupt) {
  requireHydroScene(scene, scene_name);
  const SceneDerived dv = derive(scene);
  const hydro::GranularHydro1D pde(hydroGeometry(scene, dv), constitutiveModel(scene, dv),
                                   scene.particles.count * dv.mass / scene.container.width,
                                   hydroRegularisation(scene), scene.hydro.energy_budget);
  hydro::HydroRunOptions ro = hydroRunOptions(scene, dv);
  ro.interrupt = interrupt;
  hydro::HydroSimulation sim(pde, ro);
  if (progress)
    fmt::print(progress, "  integrating up to {} cycles ({} cells)...\n", ro.max_cycles,
               scene.hydro.cells);
  return hydroRunContent(scene, dv, sim.run(), ro);
}

}  // namespace granwave
