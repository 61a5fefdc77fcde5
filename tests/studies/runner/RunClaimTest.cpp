// The claim that lets only one of the studies sharing a cache make a run at a time
// (studies/runner/RunClaim.hpp), and the per-attempt names that keep their files apart.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "studies/runner/RunCache.hpp"
#include "studies/runner/RunClaim.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

TEST(RunClaim, HeldByOneHolderAtATimeAndFreeOnceReleased) {
  testing::ScratchDir dir;
  const std::string stem = dir.file("particles-0123");
  RunClaim first(stem);
  ASSERT_TRUE(first.held());
  // flock(2) locks belong to an open file: a second open, even in this process, is refused.
  EXPECT_FALSE(RunClaim(stem).held());
  RunClaim moved = std::move(first);
  EXPECT_FALSE(first.held());
  EXPECT_FALSE(RunClaim(stem).held());
  moved.release();
  EXPECT_TRUE(RunClaim(stem).held());
}

TEST(RunClaim, ClaimsOfDifferentRunsAreIndependent) {
  testing::ScratchDir dir;
  RunClaim a(dir.file("particles-0001"));
  RunClaim b(dir.file("hydro-0002"));
  EXPECT_TRUE(a.held());
  EXPECT_TRUE(b.held());
}

TEST(RunClaim, EachAttemptLogsToItsOwnFile) {
  RunRecord r;
  r.stem = "runs/particles-0123";
  EXPECT_EQ(r.logPath(), "runs/particles-0123.log");
  r.attempt = "00000000deadbeef";
  EXPECT_EQ(r.logPath(), "runs/particles-0123.00000000deadbeef.log");
}

TEST(RunClaim, StoredRecordLeavesNoTemporaryBehind) {
  testing::ScratchDir dir;
  const RunCache cache(dir.path().string(), "build");
  RunRequest q;
  q.label = "ED dry seed 1";
  RunRecord r = cache.record(q);
  r.ok = true;
  cache.store(r);
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
  EXPECT_TRUE(std::filesystem::exists(r.recordPath()));
}

}  // namespace
}  // namespace granwave
