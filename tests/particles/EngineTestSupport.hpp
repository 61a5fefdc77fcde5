#pragma once
// Small builders shared by the engine tests: the paper's scene and a periodic gas.
#include <cmath>
#include <numbers>

#include "particles/EdSimulation.hpp"
#include "particles/InitialState.hpp"
#include "scene/Scene.hpp"

namespace granwave::test {

inline Scene paperScene(RestitutionKind law, double duration) {
  Scene s;  // defaults are the paper's values
  s.contact.restitution = law;
  s.run.duration = duration;
  return s;
}

// Periodic box of N disks at area fraction phi, no gravity, no drive, temperature T (J).
inline Scene periodicGas(int n, double phi, double temperature, double e) {
  Scene s;
  s.particles.count = n;
  const double d = s.particles.diameter;
  const double side = std::sqrt(n * std::numbers::pi * d * d / 4.0 / phi);
  s.container.width = side;
  s.container.height = side;
  s.container.periodic_x = true;
  s.container.periodic_z = true;
  s.drive.frequency = 0;
  s.drive.gamma.reset();
  s.run.gravity = 0;
  s.contact.restitution = RestitutionKind::Constant;
  s.contact.e = e;
  s.contact.friction = 0;
  s.contact.tc_enabled = false;
  s.initial.temperature = temperature;
  s.initial.placement = phi > 0.45 ? InitialPlacement::Lattice : InitialPlacement::Random;
  return s;
}

inline EdSimulation makeSimulation(const Scene& s) {
  const EngineConfig c = engineConfig(s);
  return EdSimulation(c, initialCondition(s, c));
}

inline double totalEnergy(const Observables& o) {
  return o.kinetic_energy + o.rotational_energy + o.potential_energy;
}

}  // namespace granwave::test
