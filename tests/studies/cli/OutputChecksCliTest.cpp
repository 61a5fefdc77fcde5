// Every output is checked before any work (docs/commands.md, "Files: what every command
// guarantees"): a directory the program may not write in, a name too long for it, a file or a
// device where a study needs a directory are refused at once (exit 2, one line), leaving
// nothing, not even an empty output directory. A write that fails anyway, past the file-size
// limit (ulimit -f) or into a full standard output, is exit 74 with one line and no leftovers.
#include <sys/stat.h>

#include <vector>

#include "tests/studies/cli/CliTestSupport.hpp"

namespace fs = std::filesystem;

namespace {

using granwave::testing::CliResult;
using granwave::testing::CliTest;

const std::string kTinyStudy = GRANWAVE_SOURCE_DIR "/tests/studies/data/tiny-wave-fronts.toml";

class OutputChecksCli : public CliTest {
 protected:
  bool makeRunFile() { return run("simulate -q s.toml -o run.h5").code == 0; }
  // As an unprivileged user: root may write in any directory.
  static std::string asNobody() {
    return ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups" : "";
  }
};

TEST_F(OutputChecksCli, OutputIntoAReadOnlyDirectoryIsRefusedBeforeAnyWork) {
  ASSERT_TRUE(makeRunFile());
  fs::create_directory(dir_ / "ro");
  fs::permissions(dir_ / "ro", fs::perms::owner_read | fs::perms::owner_exec |
                                   fs::perms::group_read | fs::perms::group_exec |
                                   fs::perms::others_read | fs::perms::others_exec);
  for (const std::string& command : std::vector<std::string>{
           "simulate -q s.toml -o ro/r.h5", "simulate -q s.toml --no-output --fields ro/f.h5",
           "hydro -q s.toml -o ro/h.h5", "fields run.h5 -o ro/f.h5", "export run.h5 -o ro/r.xyz",
           "study -q " + kTinyStudy + " -o ro/out"}) {
    SCOPED_TRACE(command);
    expectRefusal(run(command, asNobody()), "cannot write in");
  }
  EXPECT_TRUE(fs::is_empty(dir_ / "ro"));
}

TEST_F(OutputChecksCli, OutputNameTooLongForItsDirectoryIsRefusedInOneShortLine) {
  ASSERT_TRUE(makeRunFile());
  const std::string name(250, 'n');
  for (const std::string& command : std::vector<std::string>{
           "simulate -q s.toml -o " + name, "simulate -q s.toml --no-output --fields " + name,
           "hydro -q s.toml -o " + name, "fields run.h5 -o " + name, "export run.h5 -o " + name}) {
    SCOPED_TRACE(command.substr(0, 40));
    const CliResult r = run(command);
    expectRefusal(r, "characters is too long");
    EXPECT_LT(r.err.size(), 300u) << r.err;
  }
  EXPECT_EQ(stray("run.h5"), 0);
}

TEST_F(OutputChecksCli, StudyOutputOrCacheThatCannotBeADirectoryLeavesNoOutputDirectory) {
  write("afile", "not a directory\n");
  expectRefusal(run("study -q " + kTinyStudy + " -o afile"),
                "afile: is a regular file; -o must name a directory");
  expectRefusal(run("study -q " + kTinyStudy + " -o out --cache afile"),
                "afile: is a regular file; --cache must name a directory");
  expectRefusal(run("study -q " + kTinyStudy + " -o out --cache /dev/null"),
                "/dev/null: is a character device; --cache");
  expectRefusal(run("study -q " + kTinyStudy + " -o out --cache afile/runs"),
                "afile: is a regular file; --cache");
  EXPECT_FALSE(exists("out"));
  EXPECT_EQ(read("afile"), "not a directory\n");
}

TEST_F(OutputChecksCli, WritePastTheFileSizeLimitIsExit74WithNoLeftovers) {
  // 64 KiB: the scene, the program and its libraries load, the run file does not fit. A write
  // that fails leaves HDF5 unable to close the file, and it keeps blocks it no longer points
  // to; under the sanitizers these are suppressed as for the full-disk test (its .lsan.supp).
  const std::string limit = "ulimit -f 64; export LSAN_OPTIONS=suppressions=" GRANWAVE_SOURCE_DIR
                            "/tests/studies/cli/full_disk.lsan.supp:print_suppressions=0;";
  for (const std::string& command : std::vector<std::string>{
           "simulate -q s.toml -o r.h5", "simulate -q s.toml -o r.h5 --checkpoint-every 0.01",
           "hydro -q s.toml -o h.h5"}) {
    SCOPED_TRACE(command);
    const CliResult r = run(command, limit);
    EXPECT_TRUE(r.code == 74 || r.code == 75) << r.code << " " << r.err;
    EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(stray(), 0);
  }
}

TEST_F(OutputChecksCli, SummaryThatCannotBeWrittenIsExit74) {
  const CliResult r = run("simulate -q s.toml --no-output", "", "/dev/full");
  EXPECT_EQ(r.code, 74) << r.err;
  EXPECT_NE(r.err.find("standard output: cannot write the summary (No space left on device)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
