// The continuum model of a scene: each [hydro] key and the contact law select what they say
// (docs/scenes.md, docs/hydro.md), the contact pressure is in units of rho_cp g sigma, the run
// lasts the scene's duration (at least 8 cycles) after a two-cycle ramp, and e_eff at T0 is the
// Maxwell average of the law (a constant law gives its own e back).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/SceneParser.hpp"
#include "studies/hydro_run/HydroModel.hpp"

namespace granwave {
namespace {

Scene paper(const char* law, std::vector<std::string> overrides = {}) {
  return parseSceneFile(std::string(GRANWAVE_SOURCE_DIR) + "/scenes/paper-" + law + ".toml",
                        overrides);
}

}  // namespace

TEST(HydroModel, ScenesKeysSelectTheClosures) {
  const Scene s =
      paper("wet", {"hydro.transport=\"garzo-dufty\"", "hydro.pair_correlation=\"henderson\"",
                    "hydro.particles=\"rough\""});
  const SceneDerived dv = derive(s);
  const hydro::ConstitutiveModel m = constitutiveModel(s, dv);
  EXPECT_EQ(m.transport, hydro::TransportSet::GarzoDufty);
  EXPECT_EQ(m.pair_correlation.form, hydro::PairCorrelation::Form::Henderson);
  EXPECT_TRUE(m.rough.enabled);
  EXPECT_EQ(m.rough.friction, s.contact.friction);
  EXPECT_DOUBLE_EQ(m.rough.inertia, 0.4);  // a solid sphere: q = 4 I / (m d^2) = 2/5
  EXPECT_EQ(m.mass, dv.mass);
  EXPECT_EQ(m.sigma, s.particles.diameter);
  const double theta = 0.01;  // m^2/s^2
  EXPECT_DOUBLE_EQ(m.restitution.phiW(theta),
                   hydro::RestitutionClosure::wet(s.contact.e_inf, dv.v_c).phiW(theta));
  EXPECT_DOUBLE_EQ(m.wall_restitution.phiW(theta), m.restitution.phiW(theta));
}

TEST(HydroModel, ContactPressureIsInUnitsOfCloselyPackedWeight) {
  const Scene s = paper("dry", {"hydro.contact_pressure=2"});
  const SceneDerived dv = derive(s);
  const double d = s.particles.diameter;
  // rho_cp g sigma: the mass per area at hexagonal close packing, pi / (2 sqrt 3), times g d.
  const double rho_cp =
      std::numbers::pi / (2 * std::sqrt(3.0)) * dv.mass / (std::numbers::pi * d * d / 4);
  EXPECT_NEAR(constitutiveModel(s, dv).contact.scale, 2 * rho_cp * s.run.gravity * d,
              1e-12 * rho_cp * s.run.gravity * d);
}

TEST(HydroModel, ConstantModelOfAVelocityLawUsesTheConstantE) {
  const Scene s = paper("dry", {"hydro.restitution_model=\"constant\"", "contact.e=0.8"});
  EXPECT_NEAR(constitutiveModel(s, derive(s)).restitution.phiW(0.01), 1 - 0.8 * 0.8, 1e-12);
}

TEST(HydroModel, RunLastsTheScenesDurationAfterATwoCycleRamp) {
  const Scene s = paper("dry", {"run.duration=30"});
  const SceneDerived dv = derive(s);
  EXPECT_DOUBLE_EQ(hydroGeometry(s, dv).ramp_time, 2 / s.drive.frequency);
  EXPECT_EQ(hydroGeometry(s, dv).cells, s.hydro.cells);
  EXPECT_EQ(hydroRunOptions(s, dv).max_cycles, static_cast<int>(30 * s.drive.frequency));
  const Scene brief = paper("dry", {"run.duration=0.2"});
  EXPECT_EQ(hydroRunOptions(brief, derive(brief)).max_cycles, 8);
  EXPECT_EQ(hydroRunOptions(s, dv).samples_per_cycle, s.run.phases_per_cycle);
}

TEST(HydroModel, EffectiveRestitutionOfAConstantLawIsItsE) {
  EXPECT_NEAR(effectiveRestitutionAtT0(
                  paper("dry", {"contact.restitution=\"constant\"", "contact.e=0.85"})),
              0.85, 1e-12);
  // A velocity-dependent law: sqrt(1 - Phi_W) of its closure at theta0 = v0^2 / 2, whatever
  // restitution model the scene's hydro runs use.
  const Scene wet = paper("wet", {"hydro.restitution_model=\"constant\""});
  const SceneDerived dv = derive(wet);
  const double phi =
      hydro::RestitutionClosure::wet(wet.contact.e_inf, dv.v_c).phiW(0.5 * dv.v0 * dv.v0);
  EXPECT_NEAR(effectiveRestitutionAtT0(wet), std::sqrt(1 - phi), 1e-12);
}

}  // namespace granwave
