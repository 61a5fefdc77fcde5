// What `granwave study` says before a follow-up round: the round, its runs and the reason, the
// most that may follow, and the wall time at the pace of the study's finished runs of the same
// kind and size.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "studies/study_run/FollowUpProgress.hpp"

namespace granwave {
namespace {

RunRecord finished(RunKind kind, const std::string& label, double duration, double wall) {
  RunRecord r;
  r.request = runRequest(kind, label, Scene{});
  r.request.scene.run.duration = duration;
  r.ok = true;
  r.wall = wall;
  return r;
}

RunSet studySoFar() {
  return RunSet({finished(RunKind::Particles, "ED dry seed 1", 30, 100),
                 finished(RunKind::Particles, "ED dry seed 2", 30, 200),
                 finished(RunKind::Particles, "ED dry 5 s", 5, 20),
                 finished(RunKind::Hydro, "hydro dry", 0, 5)});
}

FollowUp fourMoreSeeds() {
  FollowUp more;
  for (int i = 0; i < 4; ++i) {
    RunRequest q = runRequest(RunKind::Particles, "ED dry seed " + std::to_string(3 + i), Scene{});
    q.scene.run.duration = 30;
    more.runs.push_back(q);
  }
  more.reason = "the dry law's simplest-model verdict is undecided over 2 seeds";
  more.rounds_after = 2;
  more.runs_after = 8;
  return more;
}

TEST(FollowUpProgress, ExpectedWallIsTheMeanOfFinishedRunsOfTheSameKindAndSize) {
  const RunSet done = studySoFar();
  EXPECT_DOUBLE_EQ(expectedWall(fourMoreSeeds().runs.front(), done), 150);
  RunRequest other = runRequest(RunKind::Particles, "ED dry 60 s", Scene{});
  other.scene.run.duration = 60;  // no finished run that long: every particle run
  EXPECT_DOUBLE_EQ(expectedWall(other, done), (100 + 200 + 20) / 3.0);
  EXPECT_DOUBLE_EQ(expectedWall(runRequest(RunKind::Lammps, "LAMMPS", Scene{}), done), 0);
}

TEST(FollowUpProgress, LineSaysWhyHowManyMayFollowAndHowLongAtThePaceSoFar) {
  const std::string line = followUpLine(2, fourMoreSeeds(), studySoFar(), 2);
  EXPECT_EQ(line,
            "follow-up round 2: 4 more runs, because the dry law's simplest-model verdict is "
            "undecided over 2 seeds; at most 2 more rounds (8 runs) may follow; this round about "
            "5.0 min, all that may follow at most about 10.0 min (2 at a time, at the pace of "
            "this study's runs so far)");
}

TEST(FollowUpProgress, LastPossibleRoundAndUnknownPaceAreSaid) {
  FollowUp last = fourMoreSeeds();
  last.rounds_after = 0;
  last.runs_after = 0;
  const std::string line = followUpLine(9, last, RunSet({}), 1);
  EXPECT_NE(line.find("no further round can follow"), std::string::npos) << line;
  EXPECT_NE(line.find("no estimate of time"), std::string::npos) << line;
}

}  // namespace
}  // namespace granwave
