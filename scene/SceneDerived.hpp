#pragma once
// Quantities derived from a Scene by the paper's formulas (Methods section):
//   A = Gamma g / (2 pi f)^2, v0 = Gamma g / (2 pi f), T0 = m v0^2 / 2,
//   m = rho pi d^3 / 6, I = m d^2 / 10,
//   t_c = 2.94 (m/k)^(2/5) v0^(-1/5) with k = 4 E sqrt(d) / (15 (1 - sigma^2)),
//   q = rho d / (9 eta), v_c = St_c / q,
//   kappa_SI = kappa u^(-1/5) for the dry law's velocity unit u (1 m/s, sqrt(g d) or 1 cm/s).
#include <cstdint>

#include "scene/Scene.hpp"

namespace granwave {

struct SceneDerived {
  double mass = 0;       // kg
  double inertia = 0;    // kg m^2
  double omega = 0;      // rad/s, 2 pi f (0 without drive)
  double amplitude = 0;  // m, A
  double gamma = 0;      // peak plate acceleration / g
  double v0 = 0;         // m/s, peak plate velocity
  double T0 = 0;         // J, m v0^2 / 2
  double hertz_k = 0;    // Pa m^(1/2), k of the TC formula
  double tc = 0;         // s, TC time actually used (0 when TC is off)
  double q = 0;          // s/m, Stokes-number factor
  double v_c = 0;        // m/s, wet onset velocity
  // kappa of the dry law for v_n in m/s: kappa u^(-1/5) for the scene's unit u (exactly
  // contact.kappa when u = 1 m/s).
  double kappa_si = 0;  // (s/m)^(1/5)
  bool driven = false;
};

// Paper's TC time for mass m, Hertz constant k, collision velocity v.
double tcContactDuration(double mass, double hertz_k, double velocity);

// The velocity unit u (m/s) of the dry law's v_n for the given reading.
double kappaVelocityUnit(KappaUnits units, double gravity, double diameter);

SceneDerived derive(const Scene& scene);

// The time between two records (s): one phase, 1 / (f M), in a driven scene; else
// run.record_interval, or duration / 100 when that is 0 (docs/scenes.md, [run]).
double recordInterval(const Scene& scene);

// The step of a run's last record: records are made at k x recordInterval for k = 0, 1, ...
// up to the duration (within 1e-12 of it, as the engine decides). A trajectory stride of this
// value keeps the first and the last frame only.
std::uint64_t lastRecordStep(const Scene& scene);

}  // namespace granwave
