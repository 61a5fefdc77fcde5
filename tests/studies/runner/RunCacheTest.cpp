// How the run cache names runs (by what determines their result) and records their outcome.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "studies/runner/RunCache.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace fs = std::filesystem;

namespace {

// A scratch directory per test, removed afterwards.
class StudyRunCacheTest : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  granwave::testing::ScratchDir scratch_;
  const fs::path& dir_ = scratch_.path();
};

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

// A study's particle run keeps its first and last frame only (the default scene: 15 s at
// 10 Hz and 100 phases per cycle, records 0 to 15000); a hydro run's scene is left as given.
TEST_F(StudyRunCacheTest, ParticleRunKeepsTheFirstAndTheLastFrameOnly) {
  const granwave::RunCache cache((dir_ / "runs").string(), "build-a");
  const granwave::RunRecord r = cache.record(particleRequest());
  EXPECT_EQ(r.request.scene.run.trajectory_stride, 15000);
  granwave::RunRequest q = particleRequest();
  q.kind = granwave::RunKind::Hydro;
  EXPECT_EQ(cache.record(q).request.scene.run.trajectory_stride, 1);
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
