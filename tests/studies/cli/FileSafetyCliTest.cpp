// What every command guarantees about the files it is given (docs/commands.md, "Files: what
// every command guarantees"): devices, FIFOs and directories are refused as outputs and
// inputs before any work; no output may be an input or another output (the XDMF sidecar
// included); errors stay one line; NaN options, unnamed restitution laws and empty or
// truncated scenes are refused; running out of memory has its own exit code.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "AddressSanitizer.hpp"
#include "tests/studies/cli/CliTestSupport.hpp"

namespace fs = std::filesystem;
using granwave::testing::CliResult;
using granwave::testing::kShortDryScene;

namespace {

class FileSafetyCli : public granwave::testing::CliTest {
 protected:
  bool makeRunFile() const { return run("simulate -q s.toml -o run.h5").code == 0; }
};

}  // namespace

TEST_F(FileSafetyCli, DeviceOutputIsRefusedAndStaysADevice) {
  for (const std::string command : {"simulate -q s.toml", "hydro -q s.toml"}) {
    expectRefusal(run(command + " -o /dev/full"), "/dev/full: is a character device");
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
  }
  if (::geteuid() != 0) GTEST_SKIP() << "a private device node needs root (mknod)";
  // A private copy of /dev/null: as root, renaming over it would have replaced it.
  ASSERT_EQ(::mknod((dir_ / "mynull").c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);
  expectRefusal(run("simulate -q s.toml -o mynull"), "mynull: is a character device");
  EXPECT_TRUE(fs::is_character_file(dir_ / "mynull"));
}

TEST_F(FileSafetyCli, DirectoryOutputIsRefusedBeforeAnyWorkAndNothingGoesIntoIt) {
  for (const std::string out : {"/", ".", "sub/"}) {
    expectRefusal(run("simulate -q s.toml -o " + out), "directory");
    EXPECT_EQ(stray(), 0) << out;
  }
  expectRefusal(run("simulate -q s.toml -o nosuch/run.h5"), "nosuch does not exist");
}

TEST_F(FileSafetyCli, OutputOverTheSceneOrAnotherOutputIsRefusedBeforeTheRun) {
  expectRefusal(run("simulate -q s.toml -o s.toml"), "would overwrite the scene");
  EXPECT_EQ(slurp(dir_ / "s.toml"), kShortDryScene);
  expectRefusal(run("simulate -q s.toml -o r.h5 --fields r.h5"), "would be the same file");
  expectRefusal(run("simulate -q s.toml -o r.h5 --fields ./r.h5"), "would be the same file");
  expectRefusal(run("simulate -q s.toml -o r.h5 --fields f.xdmf"), "fields sidecar");
  expectRefusal(run("simulate -q s.toml -o f.xdmf --fields f.h5"), "fields sidecar");
  expectRefusal(run("hydro -q s.toml -o s.toml"), "would overwrite the scene");
  EXPECT_EQ(stray(), 0);
}

TEST_F(FileSafetyCli, FieldsAndExportRefuseToOverwriteTheirRunFile) {
  ASSERT_TRUE(makeRunFile());
  const std::string before = slurp(dir_ / "run.h5");
  expectRefusal(run("fields run.h5 -o run.h5"), "would overwrite the run file");
  expectRefusal(run("fields run.h5 -o run.xdmf"), "would be the same file");
  expectRefusal(run("fields run.h5 -o /dev/full"), "/dev/full: is a character device");
  expectRefusal(run("export run.h5 -o /dev/full"), "/dev/full: is a character device");
  fs::create_hard_link(dir_ / "run.h5", dir_ / "link.h5");
  expectRefusal(run("fields run.h5 -o link.h5"), "would overwrite the run file");
  expectRefusal(run("export run.h5 -o link.h5"), "would overwrite the run file");
  EXPECT_EQ(slurp(dir_ / "run.h5"), before);
}

TEST_F(FileSafetyCli, FailedFieldsStepLeavesNeitherTheFieldsNorTheRunFile) {
  // 0.3 s (3 cycles) holds no steady cycle to average: the fields analysis fails at the end.
  const CliResult r = run("simulate -q s.toml -o r.h5 --fields f.h5");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("no steady cycles"), std::string::npos) << r.err;
  EXPECT_EQ(stray(), 0) << "the run file of a failed --fields run was left";
}

TEST_F(FileSafetyCli, FifoAndDeviceInputsAreRefusedWithoutBlocking) {
  ASSERT_EQ(::mkfifo((dir_ / "pipe").c_str(), 0600), 0);
  for (const std::string command : {"simulate -q", "hydro -q", "fields", "export", "study -q"})
    expectRefusal(run(command + " pipe"), "is a FIFO");
  expectRefusal(run("fields /dev/zero"), "is a character device");
}

TEST_F(FileSafetyCli, FifoOrDirectoryNamedAsAStudySceneIsSaidToBeOne) {
  ASSERT_EQ(::mkfifo((dir_ / "pipe").c_str(), 0600), 0);
  fs::create_directory(dir_ / "sub");
  std::ifstream tiny(GRANWAVE_SOURCE_DIR "/tests/studies/data/tiny-wave-fronts.toml");
  std::string text, line;
  while (std::getline(tiny, line))
    text += (line.starts_with("dry = ")   ? "dry = \"pipe\""
             : line.starts_with("wet = ") ? "wet = \"sub\""
                                          : line) +
            "\n";
  write("st.toml", text);
  expectRefusal(run("study -q st.toml -o out"), "pipe: is a FIFO; an input must be a regular file");
  write("st.toml", text.replace(text.find("dry = \"pipe\""), 12, "dry = \"s.toml\""));
  expectRefusal(run("study -q st.toml -o out"), "sub: is a directory; an input must be a regular");
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(FileSafetyCli, NanOptionsAreRefused) {
  expectRefusal(run("simulate -q s.toml --checkpoint-every nan"), "not a finite number");
  expectRefusal(run("study -q s.toml --checkpoint-every nan"), "not a finite number");
  ASSERT_TRUE(makeRunFile());
  expectRefusal(run("fields run.h5 --front-threshold nan"), "not a finite number");
}

TEST_F(FileSafetyCli, ControlCharactersInAnErrorAreEscapedToKeepItOneLine) {
  // A key with a newline and an escape sequence in it, as a careless script might pass.
  const CliResult bad = run("simulate -q s.toml --set \"$(printf 'drive.gam\\nma\\033[2J=4')\"");
  EXPECT_EQ(bad.code, 2) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_NE(bad.err.find("gam\\nma\\x1b[2J"), std::string::npos) << bad.err;
}

TEST_F(FileSafetyCli, EmptyOrTruncatedSceneIsRefusedNotRunAsTheDryScene) {
  write("empty.toml", "");
  expectRefusal(run("simulate -q empty.toml"), "empty.toml: is empty and names no restitution law");
  // paper-wet.toml cut before its [contact] section would have run the dry scene.
  std::ifstream wet(GRANWAVE_SOURCE_DIR "/scenes/paper-wet.toml");
  std::string text, line;
  while (std::getline(wet, line) && line != "[contact]") text += line + "\n";
  write("cut.toml", text);
  expectRefusal(run("simulate -q cut.toml"), "cut.toml: names no restitution law");
  expectRefusal(run("hydro -q cut.toml"), "names no restitution law");
  EXPECT_EQ(stray(), 0);
  // Named on the command line instead, the same file runs.
  EXPECT_EQ(run("simulate -q cut.toml --no-output --set run.duration=0.1 --set "
                "contact.restitution=wet")
                .code,
            0);
}

TEST_F(FileSafetyCli, OutOfMemoryHasItsOwnExitCodeAndMessage) {
#if GRANWAVE_ADDRESS_SANITIZER
  GTEST_SKIP() << "AddressSanitizer needs more address space than the limit below leaves";
#endif
  // 120 MB of address space is too little for a million grains (their state, event queue
  // and cell lists; the largest scene the ranges allow needs about 250 MB): the allocation
  // fails as it would on a small machine.
  const CliResult r =
      run("simulate -q s.toml --no-output --set particles.count=1000000 --set "
          "container.width=6 --set container.height=6 --set run.duration=0.001",
          "ulimit -v 120000;");
  expectRefusal(r, "out of memory", 71);
}
