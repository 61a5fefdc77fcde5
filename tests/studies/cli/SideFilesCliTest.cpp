// The files a run makes beside its run file and removes again (files/SideFiles.hpp: RUN.lock,
// RUN.checkpoint-K.h5md, RUN.interrupted, RUN.tmp-PID) are never a file the user named: a
// scene or an output named like one is refused before any work (exit 2, one line) and kept,
// and a file beside the run that only resembles one is left alone.
#include <vector>

#include "tests/studies/cli/CliTestSupport.hpp"

namespace {

using granwave::testing::CliTest;

class SideFilesCli : public CliTest {};

TEST_F(SideFilesCli, SceneNamedLikeASideFileOfTheRunIsRefusedAndKept) {
  for (const std::string& name : std::vector<std::string>{"r.h5.lock", "r.h5.checkpoint-1.h5md",
                                                          "r.h5.interrupted", "r.h5.tmp-999999"}) {
    SCOPED_TRACE(name);
    write(name, granwave::testing::kShortDryScene);
    expectRefusal(run("simulate -q " + name + " -o r.h5 --checkpoint-every 1"),
                  name + ": the scene is named like the");
    EXPECT_EQ(read(name), granwave::testing::kShortDryScene);
    EXPECT_FALSE(exists("r.h5"));
  }
  // Without checkpoints the partial run file of an interrupt still replaces RUN.interrupted.
  write("r.h5.interrupted", granwave::testing::kShortDryScene);
  expectRefusal(run("simulate -q r.h5.interrupted -o r.h5"), "partial run file");
}

TEST_F(SideFilesCli, OutputNamedLikeASideFileOfAnotherOutputIsRefusedAndKept) {
  write("r.h5.lock", "the user's notes\n");
  expectRefusal(run("simulate -q s.toml -o r.h5 --fields r.h5.lock --checkpoint-every 1"),
                "r.h5.lock: the fields file is named like the lock file");
  EXPECT_EQ(read("r.h5.lock"), "the user's notes\n");
  write("r.h5.tmp-12", granwave::testing::kShortDryScene);
  expectRefusal(run("hydro -q r.h5.tmp-12 -o r.h5"), "named like the temporary");
  expectRefusal(run("simulate -q s.toml -o f.h5.tmp-12 --fields f.h5"), "named like the temporary");
}

TEST_F(SideFilesCli, FilesThatOnlyResembleSideFilesSurviveACheckpointedRun) {
  write("r.h5.checkpoint-notes.txt", "kept\n");
  write("r.h5x.tmp-999999", "kept\n");
  write("r.h5.checkpoint-2.h5md.bak", "kept\n");
  const auto r = run("simulate -q s.toml -o r.h5 --checkpoint-every 0.01");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const std::string& name : std::vector<std::string>{
           "r.h5.checkpoint-notes.txt", "r.h5x.tmp-999999", "r.h5.checkpoint-2.h5md.bak"})
    EXPECT_EQ(read(name), "kept\n") << name;
  EXPECT_FALSE(exists("r.h5.lock"));
  EXPECT_FALSE(exists("r.h5.checkpoint"));
}

}  // namespace
