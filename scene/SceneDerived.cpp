#include "scene/SceneDerived.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace granwave {

double tcContactDuration(double mass, double hertz_k, double velocity) {
  return 2.94 * std::pow(mass / hertz_k, 0.4) * std::pow(velocity, -0.2);
}

double kappaVelocityUnit(KappaUnits units, double gravity, double diameter) {
  switch (units) {
    case KappaUnits::Si:
      return 1.0;
    case KappaUnits::GravityDiameter:
      return std::sqrt(gravity * diameter);
    case KappaUnits::Cgs:
      return 0.01;
  }
  return 1.0;
}

SceneDerived derive(const Scene& s) {
  SceneDerived d;
  const double dia = s.particles.diameter;
  const double g = s.run.gravity;
  d.mass = s.particles.density * std::numbers::pi * dia * dia * dia / 6.0;
  d.inertia = d.mass * dia * dia / 10.0;
  d.driven = s.drive.frequency > 0.0;
  if (d.driven) {
    d.omega = 2.0 * std::numbers::pi * s.drive.frequency;
    if (s.drive.amplitude) {
      d.amplitude = *s.drive.amplitude;
      d.gamma = g > 0 ? d.amplitude * d.omega * d.omega / g : 0.0;
    } else {
      d.gamma = s.drive.gamma.value_or(0.0);
      d.amplitude = d.gamma * g / (d.omega * d.omega);
    }
    d.v0 = d.amplitude * d.omega;
  }
  d.T0 = 0.5 * d.mass * d.v0 * d.v0;
  const double sig = s.particles.poisson_ratio;
  d.hertz_k = 4.0 * s.particles.youngs_modulus * std::sqrt(dia) / (15.0 * (1.0 - sig * sig));
  if (s.contact.tc_enabled) {
    if (s.contact.tc_time) {
      d.tc = *s.contact.tc_time;
    } else {
      // The paper takes v0 = peak plate velocity; an undriven scene has none, so the
      // thermal speed of the initial temperature stands in (documented in docs/scenes.md).
      double v = d.v0;
      if (v <= 0 && s.initial.temperature) v = std::sqrt(2.0 * *s.initial.temperature / d.mass);
      if (v <= 0) v = std::sqrt(g * dia);
      d.tc = v > 0 ? tcContactDuration(d.mass, d.hertz_k, v) : 0.0;
    }
  }
  d.q = s.particles.density * dia / (9.0 * s.contact.viscosity);
  d.v_c = s.contact.stokes_critical / d.q;
  // e = 1 - kappa (v_n/u)^(1/5) = 1 - kappa u^(-1/5) v_n^(1/5); m/s is kept exact (default).
  const KappaUnits ku = s.contact.kappa_units;
  d.kappa_si = ku == KappaUnits::Si
                   ? s.contact.kappa
                   : s.contact.kappa * std::pow(kappaVelocityUnit(ku, g, dia), -0.2);
  return d;
}

double recordInterval(const Scene& scene) {
  if (scene.drive.frequency > 0.0)
    return 1.0 / (scene.drive.frequency * scene.run.phases_per_cycle);
  return scene.run.record_interval > 0 ? scene.run.record_interval : scene.run.duration / 100.0;
}

// The engine records at k x interval while that is within eps = 1e-12 max(duration, interval)
// of the duration (particles/EdSimulation.cpp, run()); the same comparison in doubles here.
std::uint64_t lastRecordStep(const Scene& scene) {
  const double interval = recordInterval(scene), end = scene.run.duration;
  const double eps = 1e-12 * std::max(end, interval);
  auto k = static_cast<std::uint64_t>(std::max(0.0, std::floor(end / interval)));
  while (static_cast<double>(k + 1) * interval <= end + eps) ++k;
  while (k > 0 && static_cast<double>(k) * interval > end + eps) --k;
  return k;
}

}  // namespace granwave
