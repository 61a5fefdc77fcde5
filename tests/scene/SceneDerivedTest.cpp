// Defaults and derived quantities against the paper (Huang et al., Methods and Table I;
// docs/scenes.md): q = rho d / (9 eta) = 573.3 s/m,
// v_c = St_c / q = 0.0698 m/s, A = Gamma g / (2 pi f)^2 = 9.94 mm, v0 = A 2 pi f,
// t_c = 2.94 (m/k)^(2/5) v0^(-1/5) ~ 9.2 us at f = 10 Hz, Gamma = 4.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/Scene.hpp"
#include "scene/SceneDerived.hpp"

namespace granwave {
namespace {

TEST(SceneDefaults, EqualThePapersTableIAndMethods) {
  const Scene s;
  EXPECT_EQ(s.particles.count, 300);
  EXPECT_DOUBLE_EQ(s.particles.density, 2580.0);
  EXPECT_DOUBLE_EQ(s.particles.diameter, 0.002);
  EXPECT_DOUBLE_EQ(s.particles.youngs_modulus, 63e9);
  EXPECT_DOUBLE_EQ(s.particles.poisson_ratio, 0.22);
  EXPECT_DOUBLE_EQ(s.container.width, 30 * s.particles.diameter);
  EXPECT_DOUBLE_EQ(s.container.height, 30 * s.particles.diameter);
  EXPECT_FALSE(s.container.periodic_x);
  EXPECT_FALSE(s.container.periodic_z);
  EXPECT_DOUBLE_EQ(s.drive.frequency, 10.0);
  ASSERT_TRUE(s.drive.gamma.has_value());
  EXPECT_DOUBLE_EQ(*s.drive.gamma, 4.0);
  EXPECT_FALSE(s.drive.amplitude.has_value());
  EXPECT_EQ(s.contact.restitution, RestitutionKind::Dry);
  EXPECT_DOUBLE_EQ(s.contact.kappa, 0.1);
  EXPECT_DOUBLE_EQ(s.contact.e_inf, 0.91);
  EXPECT_DOUBLE_EQ(s.contact.stokes_critical, 40.0);
  EXPECT_DOUBLE_EQ(s.contact.viscosity, 1.0e-3);
  EXPECT_DOUBLE_EQ(s.contact.friction, 0.5);
  EXPECT_DOUBLE_EQ(s.contact.tangential_limit, 0.35);
  EXPECT_EQ(s.contact.wall_tangential, ContactTangential::Smooth);
  EXPECT_EQ(s.contact.tc_tangential, ContactTangential::Smooth);
  EXPECT_EQ(s.contact.tc_window, TcWindow::Rolling);
  EXPECT_EQ(s.contact.kappa_units, KappaUnits::Si);
  EXPECT_TRUE(s.contact.tc_enabled);
  EXPECT_FALSE(s.contact.tc_time.has_value());
  EXPECT_FALSE(s.initial.temperature.has_value());
  EXPECT_EQ(s.initial.placement, InitialPlacement::Random);
  EXPECT_DOUBLE_EQ(s.run.duration, 15.0);
  EXPECT_EQ(s.run.phases_per_cycle, 100);
  EXPECT_DOUBLE_EQ(s.run.gravity, 9.81);
}

TEST(SceneDerived, PaperValuesGiveQ573AndOnsetVelocity0698) {
  const SceneDerived d = derive(Scene{});
  EXPECT_NEAR(d.q, 573.3, 0.05);
  EXPECT_NEAR(d.v_c, 0.0698, 0.00005);
}

TEST(SceneDerived, PaperDriveGivesAmplitude994MillimetresAndPeakVelocity) {
  const SceneDerived d = derive(Scene{});
  EXPECT_TRUE(d.driven);
  EXPECT_NEAR(d.amplitude, 9.94e-3, 0.005e-3);
  EXPECT_DOUBLE_EQ(d.gamma, 4.0);
  EXPECT_NEAR(d.omega, 2 * std::numbers::pi * 10.0, 1e-12);
  EXPECT_NEAR(d.v0, 4.0 * 9.81 / (2 * std::numbers::pi * 10.0), 1e-12);
  EXPECT_NEAR(d.T0, 0.5 * d.mass * d.v0 * d.v0, 1e-18);
}

TEST(SceneDerived, MassAndInertiaAreThoseOfAGlassSphere) {
  const SceneDerived d = derive(Scene{});
  EXPECT_NEAR(d.mass, 2580.0 * std::numbers::pi * 8e-9 / 6.0, 1e-15);
  EXPECT_NEAR(d.inertia, d.mass * 4e-6 / 10.0, 1e-20);
}

TEST(SceneDerived, TcAutoIsAbout9Point2MicrosecondsAtPaperDrive) {
  const SceneDerived d = derive(Scene{});
  EXPECT_NEAR(d.tc, 9.2e-6, 0.05e-6);
  EXPECT_NEAR(d.hertz_k, 4 * 63e9 * std::sqrt(0.002) / (15 * (1 - 0.22 * 0.22)), 1.0);
}

TEST(SceneDerived, TcGivenInSecondsIsUsedAsIsAndOffGivesZero) {
  Scene s;
  s.contact.tc_time = 2e-5;
  EXPECT_DOUBLE_EQ(derive(s).tc, 2e-5);
  s.contact.tc_enabled = false;
  EXPECT_DOUBLE_EQ(derive(s).tc, 0.0);
}

TEST(SceneDerived, AmplitudeGivenDerivesGamma) {
  Scene s;
  s.drive.gamma.reset();
  s.drive.amplitude = 0.005;
  const SceneDerived d = derive(s);
  const double omega = 2 * std::numbers::pi * 10.0;
  EXPECT_DOUBLE_EQ(d.amplitude, 0.005);
  EXPECT_NEAR(d.gamma, 0.005 * omega * omega / 9.81, 1e-12);
}

TEST(SceneDerived, UndrivenSceneHasNoPlateMotionAndTcFromThermalSpeed) {
  Scene s;
  s.drive.frequency = 0;
  s.initial.temperature = 1e-6;
  const SceneDerived d = derive(s);
  EXPECT_FALSE(d.driven);
  EXPECT_EQ(d.amplitude, 0.0);
  EXPECT_EQ(d.v0, 0.0);
  const double thermal = std::sqrt(2.0 * 1e-6 / d.mass);
  EXPECT_NEAR(d.tc, tcContactDuration(d.mass, d.hertz_k, thermal), 1e-15);
}

TEST(SceneDerived, UndrivenSceneWithoutTemperatureTakesTcFromSqrtGD) {
  Scene s;
  s.drive.frequency = 0;
  const SceneDerived d = derive(s);
  EXPECT_NEAR(d.tc, tcContactDuration(d.mass, d.hertz_k, std::sqrt(9.81 * 0.002)), 1e-15);
}

TEST(SceneDerived, KappaReadingsGiveTheDryRestitutionAtOneMetrePerSecondOfEachUnit) {
  // e_dry(1 m/s) = 1 - kappa_SI for kappa = 0.1 read with v_n in m/s, in units of sqrt(g d)
  // (g = 9.81, d = 2 mm: u = 0.1401 m/s) and in cm/s: 0.90, 0.852, 0.749 (kappa u^(-1/5)).
  Scene s;
  EXPECT_EQ(derive(s).kappa_si, 0.1);  // bit-identical default
  s.contact.kappa_units = KappaUnits::GravityDiameter;
  EXPECT_NEAR(derive(s).kappa_si, 0.1 * std::pow(std::sqrt(9.81 * 0.002), -0.2), 1e-15);
  EXPECT_NEAR(1.0 - derive(s).kappa_si, 0.852, 0.0005);
  s.contact.kappa_units = KappaUnits::Cgs;
  EXPECT_NEAR(derive(s).kappa_si, 0.1 * std::pow(100.0, 0.2), 1e-15);
  EXPECT_NEAR(1.0 - derive(s).kappa_si, 0.749, 0.0005);
}

}  // namespace
}  // namespace granwave
