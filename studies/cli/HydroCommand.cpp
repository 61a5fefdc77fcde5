#include "studies/cli/HydroCommand.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>

#include "coarse_grain/FieldGrid.hpp"
#include "coarse_grain/WaveFront.hpp"
#include "files/OutputPath.hpp"
#include "hydro/HydroSimulation.hpp"
#include "scene/SceneDerived.hpp"
#include "scene/SceneParser.hpp"
#include "studies/cli/OptionChecks.hpp"
#include "studies/framework/StudyScenes.hpp"
#include "studies/run_files/HydroRunFile.hpp"

namespace granwave {

namespace {

// Plate-frame profiles of one phase (cell centres z, moving with the mass) mapped onto the lab
// grid: linear between cell centres, the outermost cells' values out to the layer's edges, and
// no particles (NaN temperature and velocity) outside the layer or the container.
void mapToLab(const hydro::HydroPhase& ph, double height, const FieldGrid& grid,
              double plate_velocity, double mass, std::vector<double>& nu, std::vector<double>& T,
              std::vector<double>& uz) {
  const std::size_t N = ph.z.size();
  for (int j = 0; j < grid.nz; ++j) {
    const double zp = grid.zCentre(j) - ph.plate_height;  // z' above the plate
    if (zp < ph.layer_bottom || zp > ph.layer_top || zp < 0 || zp > height) {
      nu.push_back(0.0);
      T.push_back(kNaN);
      uz.push_back(kNaN);
      continue;
    }
    const auto above = std::upper_bound(ph.z.begin(), ph.z.end(), zp);
    const std::size_t i =
        std::min<std::size_t>(std::max<std::ptrdiff_t>(above - ph.z.begin(), 1) - 1, N - 2);
    const double w = std::clamp((zp - ph.z[i]) / (ph.z[i + 1] - ph.z[i]), 0.0, 1.0);
    auto lerp = [&](const std::vector<double>& v) { return (1 - w) * v[i] + w * v[i + 1]; };
    nu.push_back(lerp(ph.area_fraction));
    T.push_back(mass * lerp(ph.theta));  // T = m theta, J: the ED's T_g
    uz.push_back(lerp(ph.u) + plate_velocity);
  }
}

// The paper's continuum: the scene's closures (the same restitution law at the walls).
hydro::ConstitutiveModel constitutiveModel(const Scene& scene, const SceneDerived& dv) {
  const double d = scene.particles.diameter;
  hydro::ConstitutiveModel model;
  model.mass = dv.mass;
  model.sigma = d;
  model.restitution = restitutionClosure(scene);
  model.wall_restitution = model.restitution;  // the paper: the same law at the walls
  model.transport = scene.hydro.transport == HydroTransport::GarzoDufty
                        ? hydro::TransportSet::GarzoDufty
                        : hydro::TransportSet::JenkinsRichman;
  model.knudsen_length = d;
  model.pair_correlation.form = scene.hydro.pair_correlation == HydroPairCorrelation::Henderson
                                    ? hydro::PairCorrelation::Form::Henderson
                                    : hydro::PairCorrelation::Form::Luding;
  // hydro.contact_pressure is in units of rho_cp g sigma (docs/hydro.md, "Dense layer").
  model.contact.scale = scene.hydro.contact_pressure * hydro::kHexagonalClosePacking * dv.mass /
                        model.diskArea() * scene.run.gravity * d;
  if (scene.hydro.particles == HydroParticles::Rough)  // q = 4 I/(m d^2) of a solid sphere
    model.rough =
        hydro::RoughParticles{true, scene.contact.friction, scene.contact.tangential_limit, 0.4};
  if (scene.hydro.side_walls && !scene.container.periodic_x)
    model.side_wall_width = scene.container.width;
  return model;
}

hydro::HydroGeometry geometry(const Scene& scene, const SceneDerived& dv) {
  hydro::HydroGeometry geom;
  geom.cells = scene.hydro.cells;
  geom.height = scene.container.height;
  geom.gravity = scene.run.gravity;
  geom.amplitude = dv.amplitude;
  geom.omega = dv.omega;
  geom.ramp_time = 2.0 / scene.drive.frequency;  // two cycles from the settled layer
  return geom;
}

// The numerical parameters of the discrete operator (docs/hydro.md, "Sensitivity").
hydro::HydroRegularisation regularisation(const Scene& scene) {
  hydro::HydroRegularisation r;
  r.quadratic_viscosity = scene.hydro.artificial_viscosity;
  r.wall_contact_range = scene.hydro.wall_contact_range;
  r.wall_contact_stiffness = scene.hydro.wall_contact_stiffness;
  r.packing_width = scene.hydro.packing_width;
  r.temperature_floor = scene.hydro.temperature_floor;
  return r;
}

hydro::HydroRunOptions runOptions(const Scene& scene, const SceneDerived& dv) {
  hydro::HydroRunOptions ro;
  ro.initial_theta = scene.hydro.initial_temperature * dv.T0 / dv.mass;  // T0 = m theta0
  ro.start = scene.hydro.start == HydroStart::Spread ? hydro::HydroRunOptions::Start::Spread
                                                     : hydro::HydroRunOptions::Start::Settled;
  ro.samples_per_cycle = scene.run.phases_per_cycle;
  ro.max_cycles =
      std::max(8, static_cast<int>(std::floor(scene.run.duration * scene.drive.frequency)));
  ro.cvode.rtol = scene.hydro.rtol;
  ro.atol_scale = scene.hydro.atol;
  return ro;
}

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

// Lab-frame profiles on the coarse-graining grid, and the same fronts as `fields` finds.
void labFrameFields(const Scene& scene, const SceneDerived& dv, const hydro::HydroResult& r,
                    int samples_per_cycle, HydroRunContent& c) {
  const FieldGrid grid = FieldGrid::forContainer(scene.container.width, scene.container.height,
                                                 dv.amplitude, scene.particles.diameter);
  PhaseFields lab;
  lab.phases = static_cast<int>(r.window.size());
  lab.nz = grid.nz;
  lab.nx = 1;
  const double dt = 1.0 / (samples_per_cycle * scene.drive.frequency);
  for (const hydro::HydroPhase& ph : r.window) {
    const double vb = dv.amplitude * dv.omega * std::cos(dv.omega * ph.time);
    mapToLab(ph, scene.container.height, grid, vb, dv.mass, lab.profile_area_fraction,
             lab.profile_temperature, lab.profile_velocity_z);
    c.plate_height.push_back(ph.plate_height);
    c.center_of_mass_height.push_back(ph.center_of_mass_height + ph.plate_height);
    c.time.push_back(ph.time - r.window.front().time + dt);
  }
  lab.profile_rms_velocity_x.assign(lab.profile_temperature.size(), kNaN);
  c.fronts = frontEpisodes(lab, {}, grid.z0, grid.wz, dv.T0, dt, {}, c.plate_height);
  c.rows = static_cast<std::size_t>(grid.nz);
  for (std::size_t j = 0; j < c.rows; ++j) c.lab_z.push_back(grid.zCentre(static_cast<int>(j)));
  c.front_height =
      frontHeights(lab, grid.z0, grid.wz, dv.T0, FrontOptions{}, &c.front_peak_temperature);
  c.lab_area_fraction = std::move(lab.profile_area_fraction);
  c.lab_temperature = std::move(lab.profile_temperature);
  c.lab_velocity_z = std::move(lab.profile_velocity_z);
}

HydroRunContent runContent(const Scene& scene, const SceneDerived& dv, const hydro::HydroResult& r,
                           const hydro::HydroRunOptions& ro) {
  HydroRunContent c;
  c.phases = r.window.size();
  c.cells = static_cast<std::size_t>(scene.hydro.cells);
  plateFrameFields(r, dv.mass, c);
  labFrameFields(scene, dv, r, ro.samples_per_cycle, c);
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

void printSummary(const HydroOptions& opt, const Scene& scene, const hydro::HydroResult& r,
                  const std::vector<FrontEpisode>& fronts, int samples_per_cycle,
                  const std::string& out) {
  fmt::print("scene           {}\n", opt.scene_path);
  fmt::print(
      "hydro           {} cells, {} transport, {} particles, restitution {}, rtol {:g}\n",
      scene.hydro.cells,
      scene.hydro.transport == HydroTransport::GarzoDufty ? "Garzo-Dufty" : "Jenkins-Richman",
      scene.hydro.particles == HydroParticles::Rough ? "rough" : "smooth",
      scene.hydro.restitution_model == HydroRestitutionModel::Constant
          ? "constant"
          : "velocity-dependent (Maxwell-averaged)",
      scene.hydro.rtol);
  fmt::print("periodic state  {} after {} cycles; centre-of-mass period {}\n",
             r.periodic ? "reached" : "NOT reached", r.cycles,
             r.periodic ? fmt::format("{}T", r.period) : std::string("unknown"));
  fmt::print("layer           {}\n", hydro::regimeName(r.regime));
  fmt::print(
      "cost            {:.2f} CPU-s ({:.3f} per cycle), {} steps, {} RHS evaluations, "
      "{} Jacobians, {} error-test and {} nonlinear failures\n",
      r.cpu_seconds, r.cpu_seconds / r.cycles, r.stats.steps,
      r.stats.rhs_evals + r.stats.lin_rhs_evals, r.stats.jac_evals, r.stats.err_test_fails,
      r.stats.nonlin_conv_fails);
  for (const FrontEpisode& e : fronts) {
    if (!e.from_impact) continue;
    fmt::print(
        "front           t/T {:.2f}..{:.2f}: {:.2f} +- {:.2f} m/s (lab, fit error); peak T/T0 "
        "{:.2f}\n",
        static_cast<double>(e.first_phase) / samples_per_cycle,
        static_cast<double>(e.last_phase) / samples_per_cycle, e.speed, e.fit_error,
        e.peak_temperature);
  }
  fmt::print("output          {}\n", out);
}

}  // namespace

void addHydroCommand(CLI::App& app, HydroOptions& opt) {
  CLI::App* cmd = app.add_subcommand("hydro", "Integrate the 1D granular hydrodynamics of a scene");
  cmd->add_option("scene", opt.scene_path, "Scene file (TOML; [hydro] keys, docs/scenes.md)")
      ->required()
      ->check(regularInputFile());
  cmd->add_option("-o,--output", opt.output, "Output file (HDF5); default <scene>.hydro.h5");
  cmd->add_option("--set", opt.overrides,
                  "Override a scene key: section.key=value (repeatable; default: none)")
      ->take_all();
  cmd->add_flag("-q,--quiet", opt.quiet, "No progress output");
}

int runHydro(const HydroOptions& opt) {
  const Scene scene = parseSceneFile(opt.scene_path, opt.overrides);
  std::string out = opt.output;
  if (out.empty()) out = std::filesystem::path(opt.scene_path).stem().string() + ".hydro.h5";
  files::requireDistinct({{"scene", opt.scene_path}}, {{"hydro run file", out}});
  if (scene.drive.frequency <= 0)
    throw std::runtime_error(opt.scene_path +
                             ": granwave hydro needs a driven scene (drive.frequency > 0)");
  if (scene.container.periodic_z)
    throw std::runtime_error(
        opt.scene_path + ": granwave hydro needs bottom and lid (container.periodic_z = false)");
  const SceneDerived dv = derive(scene);
  const hydro::GranularHydro1D pde(geometry(scene, dv), constitutiveModel(scene, dv),
                                   scene.particles.count * dv.mass / scene.container.width,
                                   regularisation(scene));
  const hydro::HydroRunOptions ro = runOptions(scene, dv);
  hydro::HydroSimulation sim(pde, ro);
  if (!opt.quiet)
    fmt::print(stderr, "  integrating up to {} cycles ({} cells)...\n", ro.max_cycles,
               scene.hydro.cells);
  const hydro::HydroResult r = sim.run();
  const HydroRunContent content = runContent(scene, dv, r, ro);
  writeHydroRunFile(out, content);
  printSummary(opt, scene, r, content.fronts, ro.samples_per_cycle, out);
  return 0;
}

}  // namespace granwave
