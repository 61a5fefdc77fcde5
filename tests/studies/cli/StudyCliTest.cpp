// `granwave study` refuses bad study files (one-line error, exit code 2, nothing written) and
// finds the shipped scenes for a study file copied out of the repository. Whole studies:
// StudyRerunTest.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <string>

#include "tests/studies/cli/StudyCliFixture.hpp"

namespace fs = std::filesystem;
using namespace granwave::testing;

namespace {

struct BadStudy {
  const char* name;
  std::string text;
  const char* must_mention;
};

// Test names and failure messages show the case, not the struct's bytes.
void PrintTo(const BadStudy& b, std::ostream* os) { *os << b.name; }

class StudyCliBadFile : public StudyCli, public ::testing::WithParamInterface<BadStudy> {};

}  // namespace

TEST_P(StudyCliBadFile, FailsWithOneLineErrorExitCode2AndWritesNothing) {
  const BadStudy& b = GetParam();
  const std::string study = write("bad.toml", b.text);
  const Result r = run("study -q " + study + " -o out");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(r.err.starts_with("granwave: ")) << r.err;
  EXPECT_NE(r.err.find("bad.toml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(b.must_mention), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "the output directory was created";
  EXPECT_FALSE(fs::exists(dir_ / "out" / "results.h5"));
}

INSTANTIATE_TEST_SUITE_P(
    EveryClass, StudyCliBadFile,
    ::testing::Values(
        BadStudy{"UnknownKind", tinyWith("kind", "kind = \"wave-front\""), "unknown study kind"},
        BadStudy{"MissingKind", tinyWith("kind", ""), "[study] kind is missing"},
        BadStudy{"UnknownKey", tinyWith("seeds", "seeds = [1]\nsedes = [2]"),
                 "unknown key 'particles.sedes' (did you mean 'seeds'?)"},
        BadStudy{"UnknownSection", tinyWith("[cost]", "[costs]"),
                 "unknown section [costs] (did you mean 'cost'?)"},
        BadStudy{"WrongType", tinyWith("seeds", "seeds = 1"), "[particles] seeds"},
        BadStudy{"MissingSceneFile", tinyWith("wet", "wet = \"nosuch-scene.toml\""),
                 "wet = 'nosuch-scene.toml': no such file (looked in "},
        BadStudy{"SceneOverrideRejected", tinyWith("set", "set = [\"drive.gama=4\"]"),
                 "drive.gama"},
        BadStudy{"MalformedToml", tinyWith("[sweep]", "[sweep"), "TOML syntax error"},
        BadStudy{"NegativeJobs", tinyWith("kind", "kind = \"wave-fronts\"\njobs = -3"),
                 "[study] jobs"},
        BadStudy{"StabilityRepeatedSeed", tinyStabilityWith("seeds", "seeds = [1, 1]"),
                 "[particles] seeds"},
        BadStudy{"StabilitySingleSeedKeyIsUnknown", tinyStabilityWith("seeds", "seed = 1"),
                 "unknown key 'particles.seed'"},
        BadStudy{"StabilityRepeatedGamma", tinyStabilityWith("gammas", "gammas = [3.0, 3.0]"),
                 "[grid] gammas"},
        BadStudy{"StabilityTooFewCycles", tinyStabilityWith("cycles", "cycles = 10"),
                 "[particles] cycles"},
        BadStudy{"SensitivityFractionsOutOfOrder",
                 tinySensitivityWith("tolerance", "tolerance = 0.05\nfront_fractions = [0.5, 0.1]"),
                 "[parameters] front_fractions"},
        BadStudy{"SensitivityFractionAboveOne",
                 tinySensitivityWith("tolerance", "tolerance = 0.05\nfront_fractions = [0.5, 1.5]"),
                 "[parameters] front_fractions"}),
    [](const auto& info) { return std::string(info.param.name); });

// A study file copied out of the repository names the scenes as the shipped ones do
// (../scenes/paper-*.toml): not beside the copy, they are found among the study files shipped
// beside the program (build/share/granwave). The study then stops at the next check, an
// unknown section, which is read after the scenes.
TEST_F(StudyCli, CopiedStudyFileFindsTheShippedScenes) {
  std::string text = tinyWith("dry", "dry = \"../scenes/paper-dry.toml\"");
  text = studyWith(write("copy.toml", text), "wet", "wet = \"../scenes/paper-wet.toml\"");
  const Result r = run("study -q " + write("copy.toml", text + "[bogus]\nx = 1\n") + " -o out");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("unknown section [bogus]"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(StudyCli, MissingStudyFileIsAnError) {
  const Result r = run("study -q nosuch-study.toml -o out");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("nosuch-study.toml"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// Every study file shipped in studies/ is one a user is told to run: --plan reads it (every key
// known, every scene found) and lists its runs, and runs, makes and writes nothing.
TEST_F(StudyCli, EveryShippedStudyFilePlansItsRunsAndPlanWritesNothing) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(GRANWAVE_SOURCE_DIR "/studies")) {
    if (entry.path().extension() != ".toml") continue;
    ++files;
    const Result r = run("study " + entry.path().string() + " -o out --plan");
    EXPECT_EQ(r.code, 0) << entry.path() << ": " << r.err;
    EXPECT_NE(r.out.find("to do"), std::string::npos) << entry.path() << ": " << r.out;
    EXPECT_NE(r.out.find("\nruns "), std::string::npos) << entry.path() << ": " << r.out;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << entry.path() << ": --plan made the output directory";
  }
  EXPECT_GE(files, 10);
}
