// The round trip through sceneToToml: every key written, and read back to the same bits.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "scene/SceneParser.hpp"
#include "tests/scene/SceneExpectations.hpp"

namespace granwave {
namespace {

using test::expectSameScene;
using ::testing::HasSubstr;

TEST(SceneToToml, RoundTripsTheDefaults) {
  const Scene s;
  expectSameScene(parseSceneString(sceneToToml(s)), s);
}

TEST(SceneToToml, RoundTripsASceneWithEveryKeyChanged) {
  const Scene s = parseSceneString("[drive]\nfrequency = 17.3\namplitude = 0.0012345678901234\n",
                                   {"particles.count=123",
                                    "particles.diameter=0.0021",
                                    "particles.density=2400.5",
                                    "particles.youngs_modulus=5.5e10",
                                    "particles.poisson_ratio=-0.1",
                                    "container.width=0.07",
                                    "container.height=0.05",
                                    "container.periodic_x=true",
                                    "contact.restitution=constant",
                                    "contact.e=0.7",
                                    "contact.kappa=0.12",
                                    "contact.e_inf=0.8",
                                    "contact.stokes_critical=33",
                                    "contact.viscosity=1.1e-3",
                                    "contact.friction=0.3",
                                    "contact.tangential_limit=-0.2",
                                    "contact.kappa_units=gd",
                                    "contact.wall_tangential=coulomb",
                                    "contact.tc=1.5e-6",
                                    "contact.tc_tangential=rough-elastic",
                                    "contact.tc_window=anchored",
                                    "contact.rest_velocity=2e-6",
                                    "initial.temperature=3e-7",
                                    "initial.placement=lattice",
                                    "run.duration=0.1",
                                    "run.phases_per_cycle=7",
                                    "run.record_interval=0.003",
                                    "run.trajectory_stride=3",
                                    "run.seed=9007199254740993",
                                    "run.gravity=9.80665",
                                    "hydro.cells=64",
                                    "hydro.dimensions=2",
                                    "hydro.columns=12",
                                    "hydro.perturbation=0.003",
                                    "hydro.remap_share=0.125",
                                    "hydro.rtol=1e-7",
                                    "hydro.atol=1e-11",
                                    "hydro.restitution_model=constant"});
  const std::string text = sceneToToml(s);
  expectSameScene(parseSceneString(text), s);
  EXPECT_EQ(sceneToToml(parseSceneString(text)), text);
}

TEST(SceneToToml, RoundTripsDoublesBitForBit) {
  Scene s;
  s.particles.density = (0.1 + 0.2) * 1e4;
  s.particles.youngs_modulus = 1.2345678901234567e11;
  s.contact.viscosity = 1.0 / 3.0;
  s.contact.rest_velocity = 5e-324;
  s.hydro.atol = 1e-10 / 3.0;
  s.run.seed = 9223372036854775807u;
  expectSameScene(parseSceneString(sceneToToml(s)), s);
}

TEST(SceneToToml, RoundTripsTcOffAndAnUndrivenPeriodicBox) {
  const Scene s = parseSceneString(
      "", {"contact.tc=off", "drive.frequency=0", "container.periodic_z=true", "run.gravity=0"});
  expectSameScene(parseSceneString(sceneToToml(s)), s);
}

TEST(SceneToToml, WritesEverySectionAndKey) {
  const std::string text = sceneToToml(Scene{});
  for (const char* key :
       {"[particles]", "count =", "poisson_ratio =", "[container]", "periodic_z =", "[drive]",
        "gamma = 4.0", "[contact]", "restitution = \"dry\"", "tc = \"auto\"",
        "rest_velocity =", "[initial]", "temperature = \"paper\"", "placement = \"random\"",
        "[run]", "seed = 1", "[hydro]", "restitution_model = \"velocity\""})
    EXPECT_THAT(text, HasSubstr(key));
}

}  // namespace
}  // namespace granwave
