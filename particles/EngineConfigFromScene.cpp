#include <algorithm>
#include <cmath>

#include "particles/EdSimulation.hpp"
#include "scene/SceneDerived.hpp"

namespace granwave {

namespace {

TangentialRule tangentialRule(ContactTangential t) {
  switch (t) {
    case ContactTangential::Smooth:
      return TangentialRule::Smooth;
    case ContactTangential::RoughElastic:
      return TangentialRule::RoughElastic;
    case ContactTangential::Coulomb:
      return TangentialRule::Coulomb;
  }
  return TangentialRule::Smooth;
}

}  // namespace

bool tracksSpin(const EngineConfig& c) {
  return c.tangential.friction > 0.0 || c.wall_tangential == TangentialRule::RoughElastic ||
         c.tc_tangential == TangentialRule::RoughElastic;
}

EngineConfig engineConfig(const Scene& scene) {
  const SceneDerived dv = derive(scene);
  EngineConfig c;
  c.diameter = scene.particles.diameter;
  c.mass = dv.mass;
  c.gravity = scene.run.gravity;
  c.width = scene.container.width;
  c.height = scene.container.height;
  c.periodic_x = scene.container.periodic_x;
  c.periodic_z = scene.container.periodic_z;
  c.plate = {dv.amplitude, dv.omega};
  switch (scene.contact.restitution) {
    case RestitutionKind::Constant:
      c.restitution = Restitution::constant(scene.contact.e);
      break;
    case RestitutionKind::Dry:
      c.restitution = Restitution::dry(dv.kappa_si);
      break;
    case RestitutionKind::Wet:
      c.restitution = Restitution::wet(scene.contact.e_inf, scene.contact.stokes_critical, dv.q);
      break;
  }
  c.tangential = {scene.contact.friction, scene.contact.tangential_limit};
  c.wall_tangential = tangentialRule(scene.contact.wall_tangential);
  c.tc_tangential = tangentialRule(scene.contact.tc_tangential);
  c.tc_window = scene.contact.tc_window == TcWindow::Anchored ? TcWindowRule::Anchored
                                                              : TcWindowRule::Rolling;
  c.tc = dv.tc;
  // The sleep rule stops a resting particle's own motion (docs/physics.md, "Resting contacts",
  // item 7). Where the plate never pulls away from the layer (Gamma <= 1, or no drive) a resting
  // layer stays at rest, and that is exact; on a layer that flies it changes the dynamics
  // measurably (the paper's wet scene), so "auto" leaves it off there.
  c.sleep = scene.contact.sleep == SleepRule::On ||
            (scene.contact.sleep == SleepRule::Auto && (!dv.driven || dv.gamma <= 1.0 + 1e-12));
  // Where "auto" leaves it off, it switches it on once a particle rattles at no gap (500
  // enduring collisions in a row, 3.5x the longest run of the paper's wet scene: 141 over 12
  // seeds; a quarter of the collapse detector's 2000 within ~t_c); with it on, such a
  // particle's group collides inelastically. "off" is off.
  c.sleep_alarm = scene.contact.sleep == SleepRule::Off ? 0 : kAutoSleepAlarm;
  c.rest_velocity = scene.contact.rest_velocity;
  c.duration = scene.run.duration;
  c.record_interval = recordInterval(scene);
  // Collapse: a collision rate per particle far above any physical one. The velocity scale is
  // the largest of plate speed, sqrt(g d) and the thermal speed.
  double v = std::max(dv.v0, std::sqrt(c.gravity * c.diameter));
  if (scene.initial.temperature)
    v = std::max(v, std::sqrt(2.0 * *scene.initial.temperature / c.mass));
  c.collapse_window = v > 0 ? 1e-3 * c.diameter / v : 1e-6;
  c.collapse_collisions = 2000;
  // 10^4 events per particle per d / v: ten times the collapse rate kept up by every particle
  // at once; far above any physical run (a dense gas makes a few per d / v), so a run that
  // hits it would never finish. The first 10^5 events per particle are free (a settling start).
  c.max_event_rate = 10.0 * scene.particles.count / c.collapse_window;
  c.max_event_rate_grace = 1e5 * scene.particles.count;
  return c;
}

}  // namespace granwave
