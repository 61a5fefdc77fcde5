// Semantic checks of a scene (docs/scenes.md, "Valid range" column): each bad value gives a
// one-line SceneError naming the file (with the line of the value), the key, the value and
// what is valid; cross-key checks (geometry, drive, packing) name the key that must change.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/SceneParser.hpp"

namespace granwave {
namespace {

using ::testing::HasSubstr;

struct InvalidCase {
  const char* name;
  const char* toml;
  std::vector<std::string> mentions;  // the first one is "key = value"
};

void PrintTo(const InvalidCase& c, std::ostream* os) { *os << c.name; }

class SceneInvalid : public ::testing::TestWithParam<InvalidCase> {};

TEST_P(SceneInvalid, IsRejectedWithOneLineNamingFileKeyValueAndValidRange) {
  const InvalidCase& c = GetParam();
  try {
    parseSceneString(c.toml, {}, "scene.toml");
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("scene.toml", 0), 0u) << message;
    for (const auto& m : c.mentions) EXPECT_THAT(message, HasSubstr(m));
  }
}

const InvalidCase kInvalid[] = {
    {"ZeroCount", "[particles]\ncount = 0", {"scene.toml:2: particles.count = 0", ">= 1"}},
    {"ZeroDiameter",
     "[particles]\ndiameter = 0",
     {"particles.diameter = 0.0", "must be in [1e-06, 1.0] (m)"}},
    {"NegativeDensity",
     "[particles]\ndensity = -1",
     {"particles.density = -1.0", "must be in [10.0, "}},
    {"ZeroYoungsModulus",
     "[particles]\nyoungs_modulus = 0",
     {"particles.youngs_modulus = 0.0", "must be in [1000.0, "}},
    {"PoissonRatioAtOneHalf",
     "[particles]\npoisson_ratio = 0.5",
     {"particles.poisson_ratio = 0.5", "(-1.0, 0.5)"}},
    {"PoissonRatioAtMinusOne",
     "[particles]\npoisson_ratio = -1",
     {"particles.poisson_ratio = -1.0", "(-1.0, 0.5)"}},
    {"ZeroWidth", "[container]\nwidth = 0", {"container.width = 0.0", "> 0"}},
    {"NegativeHeight", "[container]\nheight = -0.06", {"container.height = -0.06", "> 0"}},
    {"NegativeFrequency",
     "[drive]\nfrequency = -10",
     {"drive.frequency = -10.0", "must be 0 or in [0.01, "}},
    {"NegativeGamma",
     "[drive]\ngamma = -1",
     {"drive.gamma = -1.0", "must be 0 or in [0.001, 100.0]"}},
    {"NegativeAmplitude", "[drive]\namplitude = -0.001", {"drive.amplitude = -0.001", ">= 0"}},
    {"RestitutionAboveOne", "[contact]\ne = 1.1", {"contact.e = 1.1", "[0.0, 1.0]"}},
    {"RestitutionBelowZero", "[contact]\ne = -0.1", {"contact.e = -0.1", "[0.0, 1.0]"}},
    {"NegativeKappa",
     "[contact]\nkappa = -0.1",
     {"contact.kappa = -0.1", "must be in [0.0, 10.0]"}},
    {"EInfZero", "[contact]\ne_inf = 0", {"contact.e_inf = 0.0", "(0.0, 1.0]"}},
    {"EInfAboveOne", "[contact]\ne_inf = 1.01", {"contact.e_inf = 1.01", "(0.0, 1.0]"}},
    {"NegativeStokesCritical",
     "[contact]\nstokes_critical = -40",
     {"contact.stokes_critical = -40.0", "must be in [0.0, "}},
    {"ZeroViscosity",
     "[contact]\nviscosity = 0",
     {"contact.viscosity = 0.0", "must be in [1e-06, 1000.0]"}},
    {"NegativeFriction",
     "[contact]\nfriction = -0.5",
     {"contact.friction = -0.5", "must be in [0.0, 10.0]"}},
    {"TangentialLimitAboveOne",
     "[contact]\ntangential_limit = 1.5",
     {"contact.tangential_limit = 1.5", "[-1.0, 1.0]"}},
    {"TangentialLimitBelowMinusOne",
     "[contact]\ntangential_limit = -2",
     {"contact.tangential_limit = -2.0", "[-1.0, 1.0]"}},
    {"ZeroTcSeconds", "[contact]\ntc = 0", {"contact.tc = 0.0", "seconds in [1e-12, 1.0]"}},
    {"NegativeTcSeconds",
     "[contact]\ntc = -1e-6",
     {"contact.tc = -1e-06", "seconds in [1e-12, 1.0]"}},
    {"NegativeRestVelocity",
     "[contact]\nrest_velocity = -1e-6",
     {"contact.rest_velocity = -1e-06", "must be in [0.0, 0.01]"}},
    {"NegativeTemperature",
     "[initial]\ntemperature = -1e-7",
     {"initial.temperature = -1e-07", ">= 0"}},
    {"ZeroDuration", "[run]\nduration = 0", {"run.duration = 0.0", "must be in (0.0, "}},
    {"ZeroPhasesPerCycle", "[run]\nphases_per_cycle = 0", {"run.phases_per_cycle = 0", ">= 1"}},
    {"NegativeRecordInterval",
     "[run]\nrecord_interval = -0.1",
     {"run.record_interval = -0.1", ">= 0"}},
    {"ZeroTrajectoryStride", "[run]\ntrajectory_stride = 0", {"run.trajectory_stride = 0", ">= 1"}},
    {"NegativeGravity",
     "[run]\ngravity = -9.81",
     {"run.gravity = -9.81", "must be 0 or in [0.001, "}},
    {"KappaInSqrtGdWithoutGravity",
     "[contact]\nkappa_units = \"gd\"\n[drive]\nfrequency = 0\n[run]\ngravity = 0",
     {"contact.kappa_units = \"gd\"", "needs run.gravity > 0"}},
    {"TooFewHydroCells", "[hydro]\ncells = 7", {"hydro.cells = 7", ">= 8"}},
    {"ThreeHydroDimensions", "[hydro]\ndimensions = 3", {"hydro.dimensions = 3", "<= 2"}},
    {"NegativeHydroColumns", "[hydro]\ncolumns = -1", {"hydro.columns = -1", ">= 0"}},
    {"HardWallsInTwoDimensions",
     "[hydro]\ndimensions = 2\nwalls = \"hard\"",
     {"hydro.walls = \"hard\"", "hydro.dimensions = 1"}},
    {"LargeHydroPerturbation",
     "[hydro]\nperturbation = 0.5",
     {"hydro.perturbation = 0.5", "must be in [0.0, 0.1]"}},
    {"RemapShareOfOne",
     "[hydro]\nremap_share = 1",
     {"hydro.remap_share = 1.0", "must be in [0.0, 0.9]"}},
    {"ZeroRtol", "[hydro]\nrtol = 0", {"hydro.rtol = 0.0", "must be in [1e-12, 0.1]"}},
    {"NegativeAtol", "[hydro]\natol = -1e-9", {"hydro.atol = -1e-09", "must be in [1e-16, 0.01]"}},
    {"WidthBelowOneDiameter",
     "[container]\nwidth = 0.001\n[particles]\ncount = 1",
     {"container.width = 0.001", "smaller than one particle diameter"}},
    {"HeightBelowOneDiameter",
     "[container]\nheight = 0.0015\n[particles]\ncount = 1",
     {"container.height = 0.0015", "smaller than one particle diameter"}},
    {"PeriodicWidthBelowThreeDiameters",
     "[container]\nwidth = 0.005\nperiodic_x = true\n[particles]\ncount = 1",
     {"container.width = 0.005", "at least 3 particle diameters"}},
    {"PeriodicZWithDrive",
     "[container]\nperiodic_z = true",
     {"container.periodic_z = true", "drive.frequency = 0"}},
    // No floor: the energy balance of a box periodic along gravity is meaningless.
    {"PeriodicAlongGravity",
     "[container]\nperiodic_x = true\nperiodic_z = true\n[drive]\nfrequency = 0",
     {"container.periodic_z = true", "run.gravity = 9.81", "no floor"}},
    {"GammaTooLargeForTheContainer",
     "[drive]\ngamma = 40",
     {"drive.gamma = 40.0", "impossible geometry", "container.height - particles.diameter"}},
    {"AmplitudeTooLargeForTheContainer",
     "[drive]\namplitude = 0.029",
     {"drive.amplitude = 0.029", "impossible geometry"}},
    {"GammaWithoutGravity",
     "[run]\ngravity = 0",
     {"drive.gamma = 4.0 (default)", "give drive.amplitude"}},
    // What the placements fit (scene/PlacementCapacity.hpp), not the close-packing bound of
    // 1039 in this box: random placement jams at 0.547 of the area, the lattice holds 986.
    {"MoreParticlesThanRandomPlacementReaches",
     "[particles]\ncount = 627",
     {"particles.count = 627", "random placement jams at 0.547 of the area", "at most 626",
      "use initial.placement = \"lattice\" (at most 986)"}},
    {"MoreParticlesThanTheLatticeHolds",
     "[particles]\ncount = 987\n[initial]\nplacement = \"lattice\"",
     {"particles.count = 987", "holds at most 986"}},
    // Bounds that keep every derived quantity a normal double and the run finite
    // (docs/scenes.md, "Why these ranges").
    {"SubnormalGravity", "[run]\ngravity = 5e-324", {"run.gravity = 5e-324", "must be 0 or in"}},
    {"HugeGravity", "[run]\ngravity = 1e300", {"run.gravity = 1e+300", "must be 0 or in"}},
    {"TinyDiameter",
     "[particles]\ndiameter = 1e-300",
     {"particles.diameter = 1e-300", "must be in [1e-06, 1.0] (m)"}},
    {"MegahertzDrive", "[drive]\nfrequency = 1e6", {"drive.frequency = 1e+06", "must be 0 or in"}},
    {"DriveWithTooManyRecords",
     "[drive]\nfrequency = 1000\ngamma = 1",
     {"run.duration = 15.0 (default)", "1.5e+06 records", "at most 1e6"}},
    {"HugePhasesPerCycle",
     "[run]\nphases_per_cycle = 2000000000",
     {"run.phases_per_cycle = 2000000000", "<= 10000"}},
    {"EndlessDuration", "[run]\nduration = 1e300", {"run.duration = 1e+300", "must be in (0.0, "}},
    {"TooManyUndrivenRecords",
     "[drive]\nfrequency = 0\n[run]\nduration = 100\nrecord_interval = 1e-5",
     {"run.record_interval = 1e-05", "1e+07 records"}},
    {"TooManyStoredPositions",
     "[particles]\ncount = 1000\n[run]\nduration = 4000\nphases_per_cycle = 20",
     {"run.trajectory_stride = 1", "raise the stride"}},
    {"TinyViscosity",
     "[contact]\nviscosity = 5e-324",
     {"contact.viscosity = 5e-324", "must be in [1e-06, 1000.0] (Pa s)"}},
    {"HugeTemperature",
     "[initial]\ntemperature = 1e300",
     {"initial.temperature = 1e+300", "thermal speed", "[1e-9, 1e3] m/s"}},
    {"SubnormalTemperature",
     "[initial]\ntemperature = 5e-324",
     {"initial.temperature = 5e-324", "thermal speed"}},
    {"TooManyParticlesForMemory",
     "[particles]\ncount = 2000000",
     {"particles.count = 2000000", "<= 1000000"}},
    {"BoxWithTooManyCells",
     "[container]\nwidth = 100\nheight = 100",
     {"container.width = 100.0", "cells", "at most 1e7"}},
    {"WidthOfOneDiameter",
     "[container]\nwidth = 0.002\n[particles]\ncount = 1",
     {"container.width = 0.002", "at least 2 particle diameters (0.004 m)"}},
    {"HeightBelowTwoDiametersUndriven",
     "[container]\nheight = 0.003\n[drive]\nfrequency = 0\n[particles]\ncount = 1",
     {"container.height = 0.003", "at least 2 particle diameters"}},
    {"DefaultValueInvalidatedByAnotherKey",
     "[particles]\ndiameter = 0.1",
     {"scene.toml: container.width = 0.06 (default)", "smaller than one particle diameter"}},
};

INSTANTIATE_TEST_SUITE_P(Scene, SceneInvalid, ::testing::ValuesIn(kInvalid),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SceneValidation, OverriddenValueIsReportedAsComingFromSet) {
  try {
    parseSceneString("[contact]\ne = 0.9\n", {"contact.e=1.5"}, "scene.toml");
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_THAT(e.what(), HasSubstr("scene.toml (--set): contact.e = 1.5"));
  }
}

TEST(SceneValidation, SceneBuiltInCodeIsCheckedWithTheSameRules) {
  Scene s;
  EXPECT_NO_THROW(validateScene(s));
  s.contact.friction = -1;
  try {
    validateScene(s, "sweep point 3");
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_STREQ(
        e.what(),
        "sweep point 3: contact.friction = -1.0: must be in [0.0, 10.0] (0 = no rotation)");
  }
}

TEST(SceneValidation, PackingUpToWhatThePlacementsReachIsAccepted) {
  // Random: 0.547 * 0.06^2 / (pi 0.002^2 / 4) = 626.8 particles (random sequential adsorption
  // jams at 0.547, scene/PlacementCapacity.hpp); the resting lattice of the paper's box: 986.
  EXPECT_NO_THROW(parseSceneString("[particles]\ncount = 626\n"));
  EXPECT_NO_THROW(
      parseSceneString("[particles]\ncount = 986\n[initial]\nplacement = \"lattice\"\n"));
}

}  // namespace
}  // namespace granwave
