// Scene files: keys read into the Scene, --set overrides, the shipped scenes and the
// parse-level errors (syntax, unknown keys, types, bad --set).
// The semantic (range, geometry) errors are in SceneValidationTest.cpp, the round trip
// through sceneToToml in SceneWriterTest.cpp.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/SceneParser.hpp"
#include "tests/scene/SceneExpectations.hpp"

namespace granwave {
namespace {

using test::expectSameScene;
using ::testing::HasSubstr;

std::string sceneFile(const char* name) {
  return std::string(GRANWAVE_SOURCE_DIR) + "/scenes/" + name;
}

TEST(SceneParser, EmptyFileGivesThePaperDefaults) {
  expectSameScene(parseSceneString(""), Scene{});
}

TEST(SceneParser, ReadsEveryKeyOfEverySection) {
  const Scene s = parseSceneString(R"(
    [particles]
    count = 50
    diameter = 0.003
    density = 2500.0
    youngs_modulus = 7e10
    poisson_ratio = 0.3
    [container]
    width = 0.09
    height = 0.12
    periodic_x = true
    periodic_z = false
    [drive]
    frequency = 20.0
    amplitude = 0.001
    [contact]
    restitution = "constant"
    e = 0.8
    kappa = 0.2
    e_inf = 0.8
    stokes_critical = 30.0
    viscosity = 2e-3
    friction = 0.0
    tangential_limit = -1.0
    kappa_units = "cgs"
    wall_tangential = "rough-elastic"
    tc = 1e-5
    tc_tangential = "coulomb"
    tc_window = "anchored"
    rest_velocity = 1e-5
    [initial]
    temperature = 1e-7
    placement = "lattice"
    [run]
    duration = 2.5
    phases_per_cycle = 50
    record_interval = 0.01
    trajectory_stride = 10
    seed = 42
    gravity = 0.0
    [hydro]
    cells = 100
    rtol = 1e-5
    atol = 1e-8
    restitution_model = "constant"
  )");
  EXPECT_EQ(s.particles.count, 50);
  EXPECT_EQ(s.particles.youngs_modulus, 7e10);
  EXPECT_TRUE(s.container.periodic_x);
  EXPECT_EQ(s.drive.amplitude, 0.001);
  EXPECT_FALSE(s.drive.gamma.has_value());
  EXPECT_EQ(s.contact.restitution, RestitutionKind::Constant);
  EXPECT_EQ(s.contact.tangential_limit, -1.0);
  EXPECT_EQ(s.contact.kappa_units, KappaUnits::Cgs);
  EXPECT_EQ(s.contact.wall_tangential, ContactTangential::RoughElastic);
  EXPECT_EQ(s.contact.tc_tangential, ContactTangential::Coulomb);
  EXPECT_EQ(s.contact.tc_window, TcWindow::Anchored);
  EXPECT_EQ(s.contact.tc_time, 1e-5);
  EXPECT_EQ(s.initial.temperature, 1e-7);
  EXPECT_EQ(s.initial.placement, InitialPlacement::Lattice);
  EXPECT_EQ(s.run.trajectory_stride, 10);
  EXPECT_EQ(s.run.seed, 42u);
  EXPECT_EQ(s.run.gravity, 0.0);
  EXPECT_EQ(s.hydro.cells, 100);
  EXPECT_EQ(s.hydro.restitution_model, HydroRestitutionModel::Constant);
}

TEST(SceneParser, AcceptsIntegersWhereNumbersAreExpected) {
  const Scene s = parseSceneString("[drive]\nfrequency = 12\ngamma = 3\n[run]\nduration = 2\n");
  EXPECT_EQ(s.drive.frequency, 12.0);
  EXPECT_EQ(s.drive.gamma, 3.0);
  EXPECT_EQ(s.run.duration, 2.0);
}

TEST(SceneParser, AmplitudeClearsTheDefaultGamma) {
  const Scene s = parseSceneString("[drive]\namplitude = 0.002\n");
  EXPECT_EQ(s.drive.amplitude, 0.002);
  EXPECT_FALSE(s.drive.gamma.has_value());
}

TEST(SceneParser, TcAcceptsAutoOffAndSeconds) {
  const Scene autoTc = parseSceneString("[contact]\ntc = \"auto\"\n");
  EXPECT_TRUE(autoTc.contact.tc_enabled);
  EXPECT_FALSE(autoTc.contact.tc_time.has_value());
  const Scene off = parseSceneString("[contact]\ntc = \"off\"\n");
  EXPECT_FALSE(off.contact.tc_enabled);
  const Scene seconds = parseSceneString("[contact]\ntc = 3e-6\n");
  EXPECT_TRUE(seconds.contact.tc_enabled);
  EXPECT_EQ(seconds.contact.tc_time, 3e-6);
}

TEST(SceneParser, TemperaturePaperMeansThePapersQuietStart) {
  EXPECT_FALSE(parseSceneString("[initial]\ntemperature = \"paper\"\n").initial.temperature);
  EXPECT_EQ(parseSceneString("[initial]\ntemperature = 0\n").initial.temperature, 0.0);
}

TEST(SceneParser, UndrivenSceneWithoutGravityOrTemperatureIsAllowed) {
  const Scene s = parseSceneString("[drive]\nfrequency = 0\n[run]\ngravity = 0\n");
  EXPECT_EQ(s.drive.frequency, 0.0);
  EXPECT_EQ(s.run.gravity, 0.0);
}

TEST(SceneParser, FullyPeriodicUndrivenBoxIsAllowed) {
  const Scene s = parseSceneString(
      "[container]\nperiodic_x = true\nperiodic_z = true\n[drive]\nfrequency = 0\n"
      "[run]\ngravity = 0\n[initial]\ntemperature = 1e-6\n");
  EXPECT_TRUE(s.container.periodic_x && s.container.periodic_z);
}

TEST(SceneFiles, PaperDryIsThePapersDefaultScene) {
  expectSameScene(parseSceneFile(sceneFile("paper-dry.toml")), Scene{});
}

TEST(SceneFiles, PaperWetDiffersFromDefaultsOnlyByTheWetLaw) {
  Scene wet;
  wet.contact.restitution = RestitutionKind::Wet;
  expectSameScene(parseSceneFile(sceneFile("paper-wet.toml")), wet);
}

TEST(SceneFiles, MissingFileIsASceneErrorNamingThePath) {
  std::string message;  // stays empty unless a SceneError is thrown
  try {
    parseSceneFile("/nonexistent/scene.toml");
  } catch (const SceneError& e) {
    message = e.what();
  }
  EXPECT_THAT(message, HasSubstr("/nonexistent/scene.toml"));
}

// --- overrides ---

TEST(SceneOverrides, BareWordIsAString) {
  const Scene s = parseSceneString("", {"contact.restitution=wet"});
  EXPECT_EQ(s.contact.restitution, RestitutionKind::Wet);
}

TEST(SceneOverrides, QuotedStringNumberBooleanAndTcOffAreTomlValues) {
  const Scene s =
      parseSceneString("[drive]\ngamma = 4\n",
                       {"contact.restitution=\"constant\"", "drive.gamma=3.5",
                        "container.periodic_x=true", "contact.tc=off", "particles.count=200"});
  EXPECT_EQ(s.contact.restitution, RestitutionKind::Constant);
  EXPECT_EQ(s.drive.gamma, 3.5);
  EXPECT_TRUE(s.container.periodic_x);
  EXPECT_FALSE(s.contact.tc_enabled);
  EXPECT_EQ(s.particles.count, 200);
}

TEST(SceneOverrides, LaterOverrideWinsAndSectionsMissingFromTheFileAreCreated) {
  const Scene s = parseSceneString("", {"hydro.cells=100", "hydro.cells=200"});
  EXPECT_EQ(s.hydro.cells, 200);
}

TEST(SceneOverrides, AmplitudeReplacesAGammaGivenInTheFile) {
  const Scene s = parseSceneString("[drive]\ngamma = 3\n", {"drive.amplitude=0.004"});
  EXPECT_EQ(s.drive.amplitude, 0.004);
  EXPECT_FALSE(s.drive.gamma.has_value());
}

TEST(SceneOverrides, GammaReplacesAnAmplitudeGivenInTheFile) {
  const Scene s = parseSceneString("[drive]\namplitude = 0.004\n", {"drive.gamma=2.5"});
  EXPECT_EQ(s.drive.gamma, 2.5);
  EXPECT_FALSE(s.drive.amplitude.has_value());
}

TEST(SceneParser, OlderRoughWallsKeyMeansCoulombWalls) {
  EXPECT_EQ(parseSceneString("[contact]\nrough_walls = true").contact.wall_tangential,
            ContactTangential::Coulomb);
  EXPECT_EQ(parseSceneString("[contact]\nrough_walls = false").contact.wall_tangential,
            ContactTangential::Smooth);
}

// --- parse-level errors: one line, naming the file, the key and what is valid ---

struct ErrorCase {
  const char* name;
  const char* toml;
  std::vector<std::string> overrides;
  std::vector<std::string> mentions;
};

void PrintTo(const ErrorCase& c, std::ostream* os) { *os << c.name; }

class SceneParseError : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(SceneParseError, IsOneLineNamingFileKeyAndRemedy) {
  const ErrorCase& c = GetParam();
  try {
    parseSceneString(c.toml, c.overrides, "scene.toml");
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("scene.toml", 0), 0u) << message;
    for (const auto& m : c.mentions) EXPECT_THAT(message, HasSubstr(m));
  }
}

const ErrorCase kParseErrors[] = {
    {"TomlSyntaxErrorGivesLineAndColumn",
     "[drive]\ngamma = = 3\n",
     {},
     {"scene.toml:2:", "TOML syntax error"}},
    {"UnknownSectionSuggestsTheClosest",
     "[partcles]\ncount = 3\n",
     {},
     {"unknown section [partcles]", "did you mean 'particles'", "valid sections"}},
    {"UnknownKeySuggestsTheClosest",
     "[drive]\ngama = 3\n",
     {},
     {"scene.toml:2:", "'drive.gama'", "did you mean 'drive.gamma'", "frequency, gamma"}},
    {"KeyInTheWrongSectionSuggestsItsSection",
     "[particles]\nfriction = 0.3\n",
     {},
     {"'particles.friction'", "did you mean 'contact.friction'"}},
    {"UnknownKeyFarFromAnyGivesNoSuggestion",
     "[run]\nxyzzyplugh = 1\n",
     {},
     {"'run.xyzzyplugh'", "valid keys in [run]"}},
    {"KeyOutsideAnySection", "count = 300\n", {}, {"count = 300", "under [particles]"}},
    {"SectionThatIsNotATable", "drive = 5\n", {}, {"drive = 5", "expected a table [drive]"}},
    {"NumberGivenAsString",
     "[drive]\ngamma = \"high\"\n",
     {},
     {"drive.gamma = \"high\"", "expected a finite number"}},
    {"NotFiniteNumber", "[run]\nduration = inf\n", {}, {"run.duration = inf", "finite"}},
    {"FloatWhereIntegerExpected",
     "[particles]\ncount = 300.5\n",
     {},
     {"particles.count = 300.5", "expected an integer"}},
    {"IntegerTooLarge",
     "[hydro]\ncells = 9999999999\n",
     {},
     {"hydro.cells = 9999999999", "an integer in"}},
    {"NegativeSeed", "[run]\nseed = -1\n", {}, {"run.seed = -1", "an integer in [0,"}},
    {"BooleanGivenAsNumber",
     "[container]\nperiodic_x = 1\n",
     {},
     {"container.periodic_x = 1", "expected true or false"}},
    {"UnknownRestitutionLaw",
     "[contact]\nrestitution = \"moist\"\n",
     {},
     {"contact.restitution = \"moist\"", R"(one of "constant", "dry", "wet")"}},
    {"UnknownWallTangential",
     "[contact]\nwall_tangential = \"rough\"\n",
     {},
     {"contact.wall_tangential = \"rough\"", R"(one of "smooth", "rough-elastic", "coulomb")"}},
    {"UnknownTcTangential",
     "[contact]\ntc_tangential = 1\n",
     {},
     {"contact.tc_tangential = 1", R"("rough-elastic")"}},
    {"UnknownTcWindow",
     "[contact]\ntc_window = \"fixed\"\n",
     {},
     {"contact.tc_window = \"fixed\"", R"(one of "rolling", "anchored")"}},
    {"UnknownKappaUnits",
     "[contact]\nkappa_units = \"m/s\"\n",
     {},
     {"contact.kappa_units = \"m/s\"", R"(one of "si", "gd", "cgs")"}},
    {"UnknownHydroWalls",
     "[hydro]\nwalls = \"soft\"\n",
     {},
     {"hydro.walls = \"soft\"", R"(one of "spring", "hard")"}},
    {"UnknownPlacement",
     "[initial]\nplacement = \"grid\"\n",
     {},
     {"initial.placement", "\"lattice\""}},
    {"UnknownHydroModel",
     "[hydro]\nrestitution_model = 1\n",
     {},
     {"hydro.restitution_model = 1", "\"velocity\""}},
    {"UnknownTcWord",
     "[contact]\ntc = \"sometimes\"\n",
     {},
     {"contact.tc = \"sometimes\"", R"("auto", "off" or a time in seconds)"}},
    {"UnknownTemperatureWord",
     "[initial]\ntemperature = \"hot\"\n",
     {},
     {"initial.temperature = \"hot\"", "\"paper\""}},
    {"GammaAndAmplitudeBothGiven",
     "[drive]\ngamma = 3\namplitude = 0.001\n",
     {},
     {"drive.gamma = 3", "drive.amplitude = 0.001", "not both"}},
    {"OverrideWithoutEquals", "", {"drive.gamma"}, {"--set 'drive.gamma'", "section.key=value"}},
    {"OverrideWithoutSection", "", {"gamma=3"}, {"--set 'gamma=3'", "section.key=value"}},
    {"OverrideOfUnknownKey",
     "",
     {"drive.gama=3"},
     {"--set drive.gama=3", "did you mean 'drive.gamma'"}},
    {"OverrideOfUnknownSection",
     "",
     {"drvie.gamma=3"},
     {"--set drvie.gamma=3", "unknown section [drvie]", "did you mean 'drive'"}},
    {"OverrideOfWrongType",
     "",
     {"drive.gamma=3.5x"},
     {"(--set)", "drive.gamma = \"3.5x\"", "expected a finite number"}},
    {"OverridesGivingGammaAndAmplitude",
     "",
     {"drive.gamma=3", "drive.amplitude=0.001"},
     {"(--set)", "not both"}},
};

INSTANTIATE_TEST_SUITE_P(Scene, SceneParseError, ::testing::ValuesIn(kParseErrors),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace granwave
