// How a study file is read and checked: typed keys, defaults, unknown keys and sections, scene
// paths relative to the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "studies/contract/StudyFile.hpp"
#include "tests/h5/ScratchDir.hpp"
#include "tests/studies/contract/StudyErrorMessage.hpp"

namespace fs = std::filesystem;

namespace {

// A scratch directory per test, removed afterwards.
class StudyFileTest : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  granwave::testing::ScratchDir scratch_;
  const fs::path& dir_ = scratch_.path();
};

using granwave::testing::contains;
using granwave::testing::studyError;

const char* kTyped = R"([study]
kind = "test-kind"
[values]
x = 2.5
whole = 3
n = 7
on = true
name = "dry"
xs = [1.0, 2, 3.5]
ns = [4, 5]
names = ["a", "b"]
)";

}  // namespace

TEST_F(StudyFileTest, TypedReadsReturnTheFileValues) {
  granwave::StudyFile f = granwave::StudyFile::load(write("s.toml", kTyped));
  EXPECT_EQ(f.kind(), "test-kind");
  EXPECT_DOUBLE_EQ(f.number("values", "x", 0), 2.5);
  EXPECT_DOUBLE_EQ(f.number("values", "whole", 0), 3.0);  // an integer is a number
  EXPECT_EQ(f.integer("values", "n", 0), 7);
  EXPECT_TRUE(f.boolean("values", "on", false));
  EXPECT_EQ(f.string("values", "name", ""), "dry");
  EXPECT_EQ(f.numbers("values", "xs", {}), (std::vector<double>{1.0, 2.0, 3.5}));
  EXPECT_EQ(f.integers("values", "ns", {}), (std::vector<int>{4, 5}));
  EXPECT_EQ(f.strings("values", "names", {}), (std::vector<std::string>{"a", "b"}));
  EXPECT_NO_THROW(f.rejectUnknownKeys());
}

TEST_F(StudyFileTest, AbsentKeysAndSectionsGiveTheDefaults) {
  granwave::StudyFile f = granwave::StudyFile::load(write("s.toml", kTyped));
  EXPECT_DOUBLE_EQ(f.number("values", "missing", 1.5), 1.5);
  EXPECT_EQ(f.integer("values", "missing", 9), 9);
  EXPECT_FALSE(f.boolean("nosection", "on", false));
  EXPECT_EQ(f.string("nosection", "name", "wet"), "wet");
  EXPECT_EQ(f.numbers("nosection", "xs", {0.5}), (std::vector<double>{0.5}));
  EXPECT_EQ(f.integers("nosection", "ns", {1, 2}), (std::vector<int>{1, 2}));
  EXPECT_TRUE(f.strings("nosection", "names", {}).empty());
}

TEST_F(StudyFileTest, WrongTypeIsAStudyErrorNamingFileSectionAndKey) {
  const std::string path = write("typed.toml", kTyped);
  granwave::StudyFile f = granwave::StudyFile::load(path);
  for (const std::string& m : {studyError([&] { f.number("values", "name", 0); }),
                               studyError([&] { f.integer("values", "x", 0); }),
                               studyError([&] { f.boolean("values", "name", false); }),
                               studyError([&] { f.string("values", "on", ""); }),
                               studyError([&] { f.numbers("values", "names", {}); }),
                               studyError([&] { f.integers("values", "xs", {}); }),
                               studyError([&] { f.strings("values", "ns", {}); })}) {
    EXPECT_TRUE(contains(m, path)) << m;
    EXPECT_TRUE(contains(m, "[values] ")) << m;
    EXPECT_TRUE(contains(m, "expected")) << m;
  }
  const std::string m = studyError([&] { f.integer("values", "x", 0); });
  EXPECT_TRUE(contains(m, "[values] x = 2.5: expected an integer")) << m;
}

TEST_F(StudyFileTest, EmptyArrayIsRejectedWhereValuesAreNeeded) {
  granwave::StudyFile f = granwave::StudyFile::load(
      write("s.toml", "[study]\nkind = \"k\"\n[sweep]\ncounts = []\nxs = []\n"));
  EXPECT_TRUE(contains(studyError([&] { f.integers("sweep", "counts", {1}); }), "[sweep] counts"));
  EXPECT_TRUE(contains(studyError([&] { f.numbers("sweep", "xs", {1}); }), "[sweep] xs"));
}

TEST_F(StudyFileTest, UnknownKeyIsRejectedWithTheValidKeysListed) {
  granwave::StudyFile f = granwave::StudyFile::load(write(
      "s.toml", "[study]\nkind = \"k\"\n[particles]\nduration = 3\ndurration = 4\nseeds = [1]\n"));
  f.number("particles", "duration", 1);
  f.integers("particles", "seeds", {1});
  f.integer("particles", "blocks", 5);  // read but absent: still a valid key
  const std::string m = studyError([&] { f.rejectUnknownKeys(); });
  EXPECT_TRUE(contains(m, "s.toml")) << m;
  EXPECT_TRUE(contains(m, "unknown key 'particles.durration'")) << m;
  EXPECT_TRUE(contains(m, "valid keys in [particles]: blocks, duration, seeds")) << m;
}

TEST_F(StudyFileTest, UnknownSectionIsRejectedWithTheValidSectionsListed) {
  granwave::StudyFile f = granwave::StudyFile::load(
      write("s.toml", "[study]\nkind = \"k\"\n[particles]\nduration = 3\n[partciles]\nx = 1\n"));
  f.number("particles", "duration", 1);
  f.number("sweep", "duration", 1);
  const std::string m = studyError([&] { f.rejectUnknownKeys(); });
  EXPECT_TRUE(contains(m, "unknown section [partciles]")) << m;
  EXPECT_TRUE(contains(m, "a k study")) << m;
  EXPECT_TRUE(contains(m, "valid sections: particles, study, sweep")) << m;
}

TEST_F(StudyFileTest, MissingKindIsAStudyErrorListingTheKinds) {
  const std::string path = write("s.toml", "[particles]\nduration = 3\n");
  const std::string m = studyError([&] { granwave::StudyFile::load(path); });
  EXPECT_TRUE(contains(m, path)) << m;
  EXPECT_TRUE(contains(m, "[study] kind is missing")) << m;
  EXPECT_TRUE(contains(m, "wave-fronts")) << m;
}

TEST_F(StudyFileTest, MissingFileAndMalformedTomlAreStudyErrors) {
  const std::string missing = (dir_ / "nosuch.toml").string();
  EXPECT_TRUE(contains(studyError([&] { granwave::StudyFile::load(missing); }), missing));
  const std::string bad = write("bad.toml", "[study\nkind = \"k\"\n");
  const std::string m = studyError([&] { granwave::StudyFile::load(bad); });
  EXPECT_TRUE(contains(m, bad + ":1:")) << m;
  EXPECT_TRUE(contains(m, "TOML syntax error")) << m;
}

TEST_F(StudyFileTest, ScenePathIsRelativeToTheStudyFileAndMustExist) {
  fs::create_directories(dir_ / "scenes");
  write("scenes/dry.toml", "");
  fs::create_directories(dir_ / "studies");
  granwave::StudyFile f = granwave::StudyFile::load(
      write("studies/s.toml",
            "[study]\nkind = \"k\"\n[scenes]\ndry = \"../scenes/dry.toml\"\n"
            "wet = \"../scenes/wet.toml\"\n"));
  EXPECT_EQ(fs::path(f.scenePath("scenes", "dry", "")), (dir_ / "scenes/dry.toml"));
  const std::string m = studyError([&] { f.scenePath("scenes", "wet", ""); });
  EXPECT_TRUE(contains(m, "[scenes] wet")) << m;
  // Both places it looked: beside the study file, and among the installed study files.
  EXPECT_TRUE(
      contains(m, "no such file (looked in " + (dir_ / "scenes/wet.toml").string() + " and "))
      << m;
  EXPECT_TRUE(contains(m, "share/granwave/scenes/wet.toml)")) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
}
