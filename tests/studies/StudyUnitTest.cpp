// The study framework's pieces without running anything: how measurements combine and print,
// how impact fronts are told apart, how a study file is read and checked, and how the run
// cache names and records runs.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "studies/ImpactFronts.hpp"
#include "studies/Measurement.hpp"
#include "studies/RunCache.hpp"
#include "studies/StudyFile.hpp"

namespace fs = std::filesystem;
using granwave::Measurement;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A scratch directory per test, removed afterwards.
class ScratchDir : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("granwave_study_unit_" + std::to_string(::getpid()) + "_" +
                                        info->test_suite_name() + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  fs::path dir_;
};

}  // namespace

// ---------------------------------------------------------------------------------------------
// Measurement

TEST(StudyMeasurement, CombiningTwoConsistentEqualErrorValuesGivesTheMeanAndSigmaOverSqrt2) {
  const Measurement m = granwave::combine({{1.0, 0.1}, {1.1, 0.1}});
  EXPECT_NEAR(m.value, 1.05, 1e-12);
  EXPECT_NEAR(m.error, 0.1 / std::sqrt(2.0), 1e-12);  // chi^2 / (n - 1) = 0.5: not scaled
}

TEST(StudyMeasurement, InverseVarianceWeightsFavourTheMorePreciseValue) {
  const Measurement m = granwave::combine({{1.0, 0.1}, {1.1, 0.2}});
  // weights 100 and 25; chi^2 = 0.8 < 1, so no scale factor
  EXPECT_NEAR(m.value, (100 * 1.0 + 25 * 1.1) / 125, 1e-12);
  EXPECT_NEAR(m.error, 1 / std::sqrt(125.0), 1e-12);
}

TEST(StudyMeasurement, ScatteredValuesScaleTheErrorBySqrtChi2PerDegreeOfFreedom) {
  const Measurement m = granwave::combine({{1.0, 0.1}, {2.0, 0.1}, {3.0, 0.1}});
  EXPECT_NEAR(m.value, 2.0, 1e-12);
  const double chi2 = 100 + 0 + 100;
  EXPECT_NEAR(m.error, 0.1 / std::sqrt(3.0) * std::sqrt(chi2 / 2), 1e-12);
}

TEST(StudyMeasurement, InvalidEntriesAreIgnored) {
  const Measurement with = granwave::combine({{1.0, 0.1}, {kNaN, 0.1}, {1.1, 0.1}, {}});
  const Measurement without = granwave::combine({{1.0, 0.1}, {1.1, 0.1}});
  EXPECT_DOUBLE_EQ(with.value, without.value);
  EXPECT_DOUBLE_EQ(with.error, without.error);
}

TEST(StudyMeasurement, EntryWithoutErrorCountsWithTheMeanErrorOfTheOthers) {
  const Measurement m = granwave::combine({{1.0, 0.1}, {1.1, kNaN}});
  EXPECT_NEAR(m.value, 1.05, 1e-12);
  EXPECT_NEAR(m.error, 0.1 / std::sqrt(2.0), 1e-12);
}

TEST(StudyMeasurement, NoValidEntryGivesAnInvalidResult) {
  EXPECT_FALSE(granwave::combine({}).valid());
  EXPECT_FALSE(granwave::combine({{kNaN, 0.1}, {}}).valid());
}

TEST(StudyMeasurement, SigmaDistanceIsTheDifferenceInCombinedSigmas) {
  EXPECT_NEAR(granwave::sigmaDistance({3.0, 0.3}, {1.0, 0.4}), 4.0, 1e-12);
  EXPECT_NEAR(granwave::sigmaDistance({1.0, 0.3}, {3.0, 0.4}), -4.0, 1e-12);
  EXPECT_NEAR(granwave::sigmaDistance({3.0, kNaN}, {1.0, 0.5}), 4.0, 1e-12);  // no error: 0
  EXPECT_TRUE(std::isnan(granwave::sigmaDistance({3.0, 0.0}, {1.0, 0.0})));
}

TEST(StudyMeasurement, FormatPrintsValuePlusMinusErrorOrADashWhenInvalid) {
  EXPECT_EQ(granwave::format({1.64, 0.45}), "1.64 ± 0.45");
  EXPECT_EQ(granwave::format({1.6449, 0.4451}), "1.64 ± 0.45");
  EXPECT_EQ(granwave::format({1.64, 0.45}, 3), "1.640 ± 0.450");
  EXPECT_EQ(granwave::format({1.64, kNaN}), "1.64");
  EXPECT_EQ(granwave::format(Measurement{}), "–");
  EXPECT_EQ(granwave::formatNumber(kNaN), "–");
  EXPECT_EQ(granwave::formatNumber(0.125, 1), "0.1");
}

// ---------------------------------------------------------------------------------------------
// ImpactFronts

namespace {

granwave::Front front(double start, double speed, double error, double peak, bool impact = true) {
  granwave::Front f;
  f.start = start;
  f.speed = speed;
  f.error = error;
  f.peak = peak;
  f.from_impact = impact;
  return f;
}

}  // namespace

TEST(StudyImpactFronts, WeakImpactIsTheFrontWithTheLowerPeak) {
  // The strong front comes first in the window and is the slower one: order and speed must
  // not decide, only the peak.
  const granwave::ImpactFronts r =
      granwave::impactFronts({front(0.4, 1.2, 0.1, 6.0), front(1.4, 1.9, 0.2, 2.5)});
  EXPECT_EQ(r.count, 2);
  EXPECT_DOUBLE_EQ(r.weak.value, 1.9);
  EXPECT_DOUBLE_EQ(r.weak.error, 0.2);
  EXPECT_DOUBLE_EQ(r.weak_start, 1.4);
  EXPECT_DOUBLE_EQ(r.strong.value, 1.2);
  EXPECT_DOUBLE_EQ(r.strong.error, 0.1);
  EXPECT_DOUBLE_EQ(r.strong_start, 0.4);
  const Measurement all = granwave::combine({{1.2, 0.1}, {1.9, 0.2}});
  EXPECT_DOUBLE_EQ(r.all.value, all.value);
  EXPECT_DOUBLE_EQ(r.all.error, all.error);
}

TEST(StudyImpactFronts, FrontsNotFromAnImpactAreIgnored) {
  const granwave::ImpactFronts r =
      granwave::impactFronts({front(0.1, 5.0, 0.1, 0.5, false), front(0.4, 1.2, 0.1, 6.0),
                              front(0.7, 9.0, 0.1, 50, false), front(1.4, 1.9, 0.2, 2.5)});
  EXPECT_EQ(r.count, 2);
  EXPECT_DOUBLE_EQ(r.weak.value, 1.9);
  EXPECT_DOUBLE_EQ(r.strong.value, 1.2);
}

TEST(StudyImpactFronts, SingleImpactFrontStandsForBothImpacts) {
  const granwave::ImpactFronts r =
      granwave::impactFronts({front(0.9, 1.5, 0.1, 3.0), front(0.2, 4.0, 0.1, 9.0, false)});
  EXPECT_EQ(r.count, 1);
  EXPECT_DOUBLE_EQ(r.weak.value, 1.5);
  EXPECT_DOUBLE_EQ(r.strong.value, 1.5);
  EXPECT_DOUBLE_EQ(r.weak_start, 0.9);
  EXPECT_DOUBLE_EQ(r.strong_start, 0.9);
  EXPECT_DOUBLE_EQ(r.all.value, 1.5);
}

TEST(StudyImpactFronts, NoImpactFrontGivesInvalidSpeeds) {
  const granwave::ImpactFronts r = granwave::impactFronts({front(0.2, 4.0, 0.1, 9.0, false)});
  EXPECT_EQ(r.count, 0);
  EXPECT_FALSE(r.weak.valid());
  EXPECT_FALSE(r.strong.valid());
  EXPECT_FALSE(r.all.valid());
  EXPECT_EQ(r.weak_start, granwave::ImpactFronts::kNoPhase);
}

TEST(StudyImpactFronts, CombiningRunsCombinesEachImpactSeparately) {
  const granwave::ImpactFronts a =
      granwave::impactFronts({front(0.4, 1.0, 0.1, 6.0), front(1.4, 2.0, 0.1, 2.5)});
  const granwave::ImpactFronts b =
      granwave::impactFronts({front(0.5, 1.1, 0.1, 6.0), front(1.5, 2.1, 0.1, 2.5)});
  const granwave::ImpactFronts r = granwave::combineImpactFronts({a, b});
  EXPECT_EQ(r.count, 4);
  EXPECT_NEAR(r.weak.value, 2.05, 1e-12);
  EXPECT_NEAR(r.strong.value, 1.05, 1e-12);
  EXPECT_DOUBLE_EQ(r.weak_start, 1.4);  // the first run's
}

TEST(StudyImpactFronts, CenterOfMassMinimumPhasesFindTheLowestPointOfEachCycle) {
  // A two-cycle window, 50 phases per cycle, centre of mass z = 5 + cos(2 pi (t/T - 0.3)):
  // lowest at t/T = 0.8 and 1.8, i.e. 0.8 in both cycles.
  granwave::Profiles p;
  p.phases = 100;
  for (int k = 0; k < p.phases; ++k) {
    const double t = 2.0 * k / p.phases;
    p.phase.push_back(t);
    p.com.push_back(5 + std::cos(2 * std::numbers::pi * (t - 0.3)));
  }
  const std::vector<double> phases = granwave::centerOfMassMinimumPhases(p, 2);
  ASSERT_EQ(phases.size(), 2u);
  EXPECT_NEAR(phases[0], 0.8, 1e-12);
  EXPECT_NEAR(phases[1], 0.8, 1e-12);
  // One cycle per window: the window's single lowest point.
  const std::vector<double> one = granwave::centerOfMassMinimumPhases(p, 1);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR(one[0], 0.8, 1e-12);
}

TEST(StudyImpactFronts, CenterOfMassMinimumPhasesOfAnEmptyWindowAreNone) {
  granwave::Profiles p;
  EXPECT_TRUE(granwave::centerOfMassMinimumPhases(p, 2).empty());
  p.phases = 1;
  p.phase = {0.0};
  p.com = {1.0};
  EXPECT_TRUE(granwave::centerOfMassMinimumPhases(p, 0).empty());
  EXPECT_TRUE(granwave::centerOfMassMinimumPhases(p, 2).empty());
}

// ---------------------------------------------------------------------------------------------
// StudyFile

namespace {

using StudyFileTest = ScratchDir;

// The message of the StudyError `f` throws (fails the test if it throws nothing).
template <typename F>
std::string studyError(F&& f) {
  try {
    f();
  } catch (const granwave::StudyError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no StudyError thrown";
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

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
  EXPECT_TRUE(contains(m, "does not exist")) << m;
}

// ---------------------------------------------------------------------------------------------
// RunCache

namespace {

using StudyRunCacheTest = ScratchDir;

granwave::RunRequest particleRequest(const std::string& label = "ED dry seed 1") {
  granwave::RunRequest q;
  q.kind = granwave::RunKind::Particles;
  q.label = label;
  return q;
}

}  // namespace

TEST_F(StudyRunCacheTest, SameRequestGetsTheSameStemWhateverItsLabel) {
  const granwave::RunCache cache((dir_ / "runs").string(), "build-a");
  const std::string stem = cache.record(particleRequest()).stem;
  EXPECT_EQ(cache.record(particleRequest()).stem, stem);
  EXPECT_EQ(cache.record(particleRequest("another label")).stem, stem);
  EXPECT_EQ(fs::path(stem).parent_path(), dir_ / "runs");
  EXPECT_TRUE(fs::path(stem).filename().string().starts_with("particles-"));
  // Another cache object over the same directory and build names it the same.
  EXPECT_EQ(granwave::RunCache((dir_ / "runs").string(), "build-a").record(particleRequest()).stem,
            stem);
}

TEST_F(StudyRunCacheTest, AnythingThatChangesTheResultChangesTheStem) {
  const granwave::RunCache cache((dir_ / "runs").string(), "build-a");
  const std::string stem = cache.record(particleRequest()).stem;
  granwave::RunRequest q = particleRequest();
  q.scene.drive.gamma = 3.5;
  EXPECT_NE(cache.record(q).stem, stem);
  q = particleRequest();
  q.scene.run.seed = 2;
  EXPECT_NE(cache.record(q).stem, stem);
  q = particleRequest();
  q.window_cycles = 1;
  EXPECT_NE(cache.record(q).stem, stem);
  q = particleRequest();
  q.kind = granwave::RunKind::Hydro;
  EXPECT_TRUE(fs::path(cache.record(q).stem).filename().string().starts_with("hydro-"));
  EXPECT_NE(granwave::RunCache((dir_ / "runs").string(), "build-b").record(particleRequest()).stem,
            stem);
}

TEST_F(StudyRunCacheTest, StoredRecordLoadsBackWithItsOutcomeAndFailureMessage) {
  const granwave::RunCache cache((dir_ / "runs").string(), "build-a");
  granwave::RunRecord r = cache.record(particleRequest());
  r.ok = false;
  r.exit_code = 3;
  r.message = "inelastic collapse at t = 0.06 s: switch the TC model on (contact.tc = \"auto\")";
  r.wall = 1.25;
  r.cpu = 0.75;
  cache.store(r);
  EXPECT_TRUE(fs::exists(r.recordPath()));
  EXPECT_FALSE(fs::exists(r.recordPath() + ".tmp"));

  granwave::RunRecord back = cache.record(particleRequest());
  ASSERT_TRUE(cache.load(back));
  EXPECT_TRUE(back.reused);
  EXPECT_FALSE(back.ok);
  EXPECT_EQ(back.exit_code, 3);
  EXPECT_EQ(back.message, r.message);
  EXPECT_DOUBLE_EQ(back.wall, 1.25);
  EXPECT_DOUBLE_EQ(back.cpu, 0.75);

  r.ok = true;
  r.exit_code = 0;
  r.message.clear();
  cache.store(r);  // replaces the record
  granwave::RunRecord again = cache.record(particleRequest());
  // A successful record counts only while the run's outputs exist.
  EXPECT_FALSE(cache.load(again));
  std::ofstream(r.runPath()) << "run";
  std::ofstream(r.fieldsPath()) << "fields";
  ASSERT_TRUE(cache.load(again));
  EXPECT_TRUE(again.ok);
  EXPECT_EQ(again.exit_code, 0);
  EXPECT_EQ(again.message, "");
}

TEST_F(StudyRunCacheTest, RunWithoutRecordIsNotDone) {
  const granwave::RunCache cache((dir_ / "runs").string(), "build-a");
  granwave::RunRecord r = cache.record(particleRequest());
  std::ofstream(r.runPath()) << "outputs without a record: the run did not finish";
  EXPECT_FALSE(cache.load(r));
  EXPECT_FALSE(r.reused);
}

TEST_F(StudyRunCacheTest, CorruptRecordIsNotDone) {
  const granwave::RunCache cache((dir_ / "runs").string(), "build-a");
  granwave::RunRecord r = cache.record(particleRequest());
  std::ofstream(r.recordPath()) << "ok = tru\nexit_code = \n";
  EXPECT_FALSE(cache.load(r));
  EXPECT_FALSE(r.reused);
}
