#include "studies/hydro_run/HydroModel.hpp"

#include <algorithm>
#include <cmath>

namespace granwave {

hydro::RestitutionClosure restitutionClosure(const Scene& s) {
  if (s.hydro.restitution_model == HydroRestitutionModel::Constant ||
      s.contact.restitution == RestitutionKind::Constant)
    return hydro::RestitutionClosure::constant(s.contact.e);
  if (s.contact.restitution == RestitutionKind::Dry)
    return hydro::RestitutionClosure::dry(derive(s).kappa_si);
  return hydro::RestitutionClosure::wet(s.contact.e_inf, derive(s).v_c);
}

double effectiveRestitutionAtT0(const Scene& s) {
  Scene velocity = s;
  velocity.hydro.restitution_model = HydroRestitutionModel::Velocity;
  const SceneDerived dv = derive(s);
  return std::sqrt(1.0 - restitutionClosure(velocity).phiW(0.5 * dv.v0 * dv.v0));
}

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

hydro::HydroGeometry hydroGeometry(const Scene& scene, const SceneDerived& dv) {
  hydro::HydroGeometry geom;
  geom.cells = scene.hydro.cells;
  geom.height = scene.container.height;
  geom.gravity = scene.run.gravity;
  geom.amplitude = dv.amplitude;
  geom.omega = dv.omega;
  geom.ramp_time = 2.0 / scene.drive.frequency;  // two cycles from the settled layer
  return geom;
}

hydro::HydroRegularisation hydroRegularisation(const Scene& scene) {
  hydro::HydroRegularisation r;
  r.quadratic_viscosity = scene.hydro.artificial_viscosity;
  r.wall_contact_range = scene.hydro.wall_contact_range;
  r.wall_contact_stiffness = scene.hydro.wall_contact_stiffness;
  r.walls =
      scene.hydro.walls == HydroWalls::Hard ? hydro::WallModel::Hard : hydro::WallModel::Spring;
  r.packing_width = scene.hydro.packing_width;
  r.temperature_floor = scene.hydro.temperature_floor;
  return r;
}

hydro::HydroRunOptions hydroRunOptions(const Scene& scene, const SceneDerived& dv) {
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

}  // namespace granwave
