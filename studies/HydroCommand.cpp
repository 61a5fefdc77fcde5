#include "studies/HydroCommand.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>

#include "coarse_grain/FieldGrid.hpp"
#include "coarse_grain/WaveFront.hpp"
#include "h5/AtomicFile.hpp"
#include "hydro/HydroSimulation.hpp"
#include "scene/SceneDerived.hpp"
#include "scene/SceneParser.hpp"
#include "studies/StudyScenes.hpp"

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

}  // namespace

void addHydroCommand(CLI::App& app, HydroOptions& opt) {
  CLI::App* cmd = app.add_subcommand("hydro", "Integrate the 1D granular hydrodynamics of a scene");
  cmd->add_option("scene", opt.scene_path, "Scene file (TOML; [hydro] keys, docs/scenes.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", opt.output, "Output file (HDF5); default <scene>.hydro.h5");
  cmd->add_option("--set", opt.overrides, "Override a scene key: section.key=value")->take_all();
  cmd->add_flag("-q,--quiet", opt.quiet, "No progress output");
}

int runHydro(const HydroOptions& opt) {
  const Scene scene = parseSceneFile(opt.scene_path, opt.overrides);
  if (scene.drive.frequency <= 0)
    throw std::runtime_error(opt.scene_path +
                             ": granwave hydro needs a driven scene (drive.frequency > 0)");
  if (scene.container.periodic_z)
    throw std::runtime_error(
        opt.scene_path + ": granwave hydro needs bottom and lid (container.periodic_z = false)");
  const SceneDerived dv = derive(scene);
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
  model.contact.scale = scene.hydro.contact_pressure * hydro::kHexagonalClosePacking * dv.mass /
                        model.diskArea() * scene.run.gravity * d;
  if (scene.hydro.particles == HydroParticles::Rough)  // q = 4 I/(m d^2) of a solid sphere
    model.rough =
        hydro::RoughParticles{true, scene.contact.friction, scene.contact.tangential_limit, 0.4};
  if (scene.hydro.side_walls && !scene.container.periodic_x)
    model.side_wall_width = scene.container.width;
  hydro::HydroGeometry geom;
  geom.cells = scene.hydro.cells;
  geom.height = scene.container.height;
  geom.gravity = scene.run.gravity;
  geom.amplitude = dv.amplitude;
  geom.omega = dv.omega;
  geom.ramp_time = 2.0 / scene.drive.frequency;  // two cycles from the settled layer
  const hydro::GranularHydro1D pde(geom, model,
                                   scene.particles.count * dv.mass / scene.container.width);
  hydro::HydroRunOptions ro;
  ro.samples_per_cycle = scene.run.phases_per_cycle;
  ro.max_cycles =
      std::max(8, static_cast<int>(std::floor(scene.run.duration * scene.drive.frequency)));
  ro.cvode.rtol = scene.hydro.rtol;
  ro.atol_scale = scene.hydro.atol;
  hydro::HydroSimulation sim(pde, ro);
  if (!opt.quiet)
    fmt::print(stderr, "  integrating up to {} cycles ({} cells)...\n", ro.max_cycles, geom.cells);
  const hydro::HydroResult r = sim.run();

  // Lab-frame profiles on the coarse-graining grid, and the same fronts as `fields`.
  const FieldGrid grid =
      FieldGrid::forContainer(scene.container.width, scene.container.height, dv.amplitude, d);
  PhaseFields lab;
  lab.phases = static_cast<int>(r.window.size());
  lab.nz = grid.nz;
  lab.nx = 1;
  std::vector<double> plate, com_lab, times;
  for (const hydro::HydroPhase& ph : r.window) {
    const double vb = dv.amplitude * dv.omega * std::cos(dv.omega * ph.time);
    mapToLab(ph, geom.height, grid, vb, dv.mass, lab.profile_area_fraction, lab.profile_temperature,
             lab.profile_velocity_z);
    plate.push_back(ph.plate_height);
    com_lab.push_back(ph.center_of_mass_height + ph.plate_height);
    times.push_back(ph.time - r.window.front().time +
                    1.0 / (ro.samples_per_cycle * scene.drive.frequency));
  }
  lab.profile_rms_velocity_x.assign(lab.profile_temperature.size(), kNaN);
  const std::vector<FrontEpisode> fronts =
      frontEpisodes(lab, {}, grid.z0, grid.wz, dv.T0,
                    1.0 / (ro.samples_per_cycle * scene.drive.frequency), {}, plate);

  std::string out = opt.output;
  if (out.empty()) out = std::filesystem::path(opt.scene_path).stem().string() + ".hydro.h5";
  {
    h5::AtomicFile af(out);
    h5::File& f = af.file();
    const std::size_t P = r.window.size(), N = static_cast<std::size_t>(geom.cells), Z = grid.nz;
    std::vector<double> zp, zl(Z), n, u, T, nu, p;
    for (std::size_t j = 0; j < Z; ++j) zl[j] = grid.zCentre(static_cast<int>(j));
    for (const auto& ph : r.window) {
      zp.insert(zp.end(), ph.z.begin(), ph.z.end());
      n.insert(n.end(), ph.n.begin(), ph.n.end());
      u.insert(u.end(), ph.u.begin(), ph.u.end());
      for (double th : ph.theta) T.push_back(dv.mass * th);
      nu.insert(nu.end(), ph.area_fraction.begin(), ph.area_fraction.end());
      p.insert(p.end(), ph.pressure.begin(), ph.pressure.end());
    }
    auto put = [&](const std::string& path, const std::vector<double>& v, const h5::Shape& s,
                   const char* unit) {
      f.writeDataset(path, v, s);
      f.writeStringAttribute(path, "unit", unit);
    };
    f.createGroup("/plate_frame");
    put("/plate_frame/z", zp, {P, N}, "m");
    put("/plate_frame/number_density", n, {P, N}, "m-2");
    put("/plate_frame/velocity_z", u, {P, N}, "m s-1");
    put("/plate_frame/temperature", T, {P, N}, "J");
    put("/plate_frame/area_fraction", nu, {P, N}, "1");
    put("/plate_frame/pressure", p, {P, N}, "N m-1");
    f.createGroup("/lab_frame");
    put("/lab_frame/z", zl, {Z}, "m");
    put("/lab_frame/area_fraction", lab.profile_area_fraction, {P, Z}, "1");
    put("/lab_frame/temperature", lab.profile_temperature, {P, Z}, "J");
    put("/lab_frame/velocity_z", lab.profile_velocity_z, {P, Z}, "m s-1");
    f.createGroup("/phases");
    put("/phases/time", times, {P}, "s");
    put("/phases/plate_height", plate, {P}, "m");
    put("/phases/center_of_mass_height", com_lab, {P}, "m");
    std::vector<double> peak;
    const std::vector<double> front_height =
        frontHeights(lab, grid.z0, grid.wz, dv.T0, FrontOptions{}, &peak);
    put("/phases/front_height", front_height, {P}, "m");
    put("/phases/front_peak_temperature", peak, {P}, "1");
    f.createGroup("/fronts");
    std::vector<double> fs, fe, ff, fla, fl, fp;
    for (const auto& e : fronts) {
      fs.push_back(e.speed);
      fe.push_back(e.fit_error);
      ff.push_back(e.first_phase);
      fla.push_back(e.last_phase);
      fl.push_back(e.from_impact ? 1.0 : 0.0);
      fp.push_back(e.peak_temperature);
    }
    put("/fronts/speed", fs, {fs.size()}, "m s-1");
    put("/fronts/fit_error", fe, {fe.size()}, "m s-1");
    put("/fronts/first_phase", ff, {ff.size()}, "1");
    put("/fronts/last_phase", fla, {fla.size()}, "1");
    put("/fronts/peak_temperature", fp, {fp.size()}, "1");
    put("/fronts/from_impact", fl, {fl.size()}, "1");
    f.createGroup("/solver");
    const std::string s = "/solver";
    f.writeAttribute<std::int64_t>(s, "cells", geom.cells);
    f.writeAttribute<double>(s, "rtol", ro.cvode.rtol);
    f.writeAttribute<std::int64_t>(s, "cycles", r.cycles);
    f.writeAttribute<std::int64_t>(s, "period", r.period);
    f.writeAttribute<std::int64_t>(s, "periodic", r.periodic ? 1 : 0);
    f.writeStringAttribute(s, "regime", hydro::regimeName(r.regime));
    f.writeAttribute<double>(s, "cpu_seconds", r.cpu_seconds);
    f.writeAttribute<std::int64_t>(s, "steps", r.stats.steps);
    f.writeAttribute<std::int64_t>(s, "rhs_evals", r.stats.rhs_evals + r.stats.lin_rhs_evals);
    f.writeAttribute<std::int64_t>(s, "jacobian_evals", r.stats.jac_evals);
    f.writeAttribute<std::int64_t>(s, "error_test_failures", r.stats.err_test_fails);
    f.writeAttribute<std::int64_t>(s, "nonlinear_failures", r.stats.nonlin_conv_fails);
    f.createGroup("/parameters");
    f.writeStringDataset("/parameters/scene", sceneToToml(scene));
    af.commit();
  }

  fmt::print("scene           {}\n", opt.scene_path);
  fmt::print(
      "hydro           {} cells, {} transport, {} particles, restitution {}, rtol {:g}\n",
      geom.cells,
      scene.hydro.transport == HydroTransport::GarzoDufty ? "Garzo-Dufty" : "Jenkins-Richman",
      scene.hydro.particles == HydroParticles::Rough ? "rough" : "smooth",
      scene.hydro.restitution_model == HydroRestitutionModel::Constant
          ? "constant"
          : "velocity-dependent (Maxwell-averaged)",
      ro.cvode.rtol);
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
        static_cast<double>(e.first_phase) / ro.samples_per_cycle,
        static_cast<double>(e.last_phase) / ro.samples_per_cycle, e.speed, e.fit_error,
        e.peak_temperature);
  }
  fmt::print("output          {}\n", out);
  return 0;
}

}  // namespace granwave
