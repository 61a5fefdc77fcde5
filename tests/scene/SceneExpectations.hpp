#pragma once
// Field-by-field equality of two scenes, shared by the parser and writer tests.
#include <gtest/gtest.h>

#include "scene/Scene.hpp"

namespace granwave::test {

inline void expectSameScene(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.particles.count, b.particles.count);
  EXPECT_EQ(a.particles.diameter, b.particles.diameter);
  EXPECT_EQ(a.particles.density, b.particles.density);
  EXPECT_EQ(a.particles.youngs_modulus, b.particles.youngs_modulus);
  EXPECT_EQ(a.particles.poisson_ratio, b.particles.poisson_ratio);
  EXPECT_EQ(a.container.width, b.container.width);
  EXPECT_EQ(a.container.height, b.container.height);
  EXPECT_EQ(a.container.periodic_x, b.container.periodic_x);
  EXPECT_EQ(a.container.periodic_z, b.container.periodic_z);
  EXPECT_EQ(a.drive.frequency, b.drive.frequency);
  EXPECT_EQ(a.drive.gamma, b.drive.gamma);
  EXPECT_EQ(a.drive.amplitude, b.drive.amplitude);
  EXPECT_EQ(a.contact.restitution, b.contact.restitution);
  EXPECT_EQ(a.contact.e, b.contact.e);
  EXPECT_EQ(a.contact.kappa, b.contact.kappa);
  EXPECT_EQ(a.contact.e_inf, b.contact.e_inf);
  EXPECT_EQ(a.contact.stokes_critical, b.contact.stokes_critical);
  EXPECT_EQ(a.contact.viscosity, b.contact.viscosity);
  EXPECT_EQ(a.contact.friction, b.contact.friction);
  EXPECT_EQ(a.contact.tangential_limit, b.contact.tangential_limit);
  EXPECT_EQ(a.contact.kappa_units, b.contact.kappa_units);
  EXPECT_EQ(a.contact.wall_tangential, b.contact.wall_tangential);
  EXPECT_EQ(a.contact.tc_tangential, b.contact.tc_tangential);
  EXPECT_EQ(a.contact.tc_window, b.contact.tc_window);
  EXPECT_EQ(a.contact.tc_enabled, b.contact.tc_enabled);
  EXPECT_EQ(a.contact.tc_time, b.contact.tc_time);
  EXPECT_EQ(a.contact.rest_velocity, b.contact.rest_velocity);
  EXPECT_EQ(a.initial.temperature, b.initial.temperature);
  EXPECT_EQ(a.initial.placement, b.initial.placement);
  EXPECT_EQ(a.run.duration, b.run.duration);
  EXPECT_EQ(a.run.phases_per_cycle, b.run.phases_per_cycle);
  EXPECT_EQ(a.run.record_interval, b.run.record_interval);
  EXPECT_EQ(a.run.trajectory_stride, b.run.trajectory_stride);
  EXPECT_EQ(a.run.seed, b.run.seed);
  EXPECT_EQ(a.run.gravity, b.run.gravity);
  EXPECT_EQ(a.hydro.dimensions, b.hydro.dimensions);
  EXPECT_EQ(a.hydro.cells, b.hydro.cells);
  EXPECT_EQ(a.hydro.columns, b.hydro.columns);
  EXPECT_EQ(a.hydro.perturbation, b.hydro.perturbation);
  EXPECT_EQ(a.hydro.remap_share, b.hydro.remap_share);
  EXPECT_EQ(a.hydro.rtol, b.hydro.rtol);
  EXPECT_EQ(a.hydro.atol, b.hydro.atol);
  EXPECT_EQ(a.hydro.restitution_model, b.hydro.restitution_model);
  EXPECT_EQ(a.hydro.transport, b.hydro.transport);
  EXPECT_EQ(a.hydro.side_walls, b.hydro.side_walls);
  EXPECT_EQ(a.hydro.energy_budget, b.hydro.energy_budget);
  EXPECT_EQ(a.hydro.pair_correlation, b.hydro.pair_correlation);
  EXPECT_EQ(a.hydro.contact_pressure, b.hydro.contact_pressure);
  EXPECT_EQ(a.hydro.particles, b.hydro.particles);
}

}  // namespace granwave::test
