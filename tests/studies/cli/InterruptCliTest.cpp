// SIGTERM (and SIGINT) end every command the same way (docs/commands.md, "Exit codes"): exit
// 130, one line, no partial output and no temporary left. The signal is sent once the command
// has installed its handler (SigCgt in /proc/PID/status, proc(5)), so the test does not depend
// on timing: before that, the default action would end it with 143.
#include <signal.h>

#include <chrono>
#include <thread>
#include <vector>

#include "tests/studies/cli/CliTestSupport.hpp"

namespace {

using granwave::testing::CliResult;
using granwave::testing::CliTest;

bool catchesSigterm(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.starts_with("SigCgt:"))
      return (std::stoull(line.substr(7), nullptr, 16) >> (SIGTERM - 1)) & 1u;
  return false;
}

class InterruptCli : public CliTest {
 protected:
  // A run file of 6 s (600 records of 150 grains): fields and export take a while on it.
  void SetUp() override {
    CliTest::SetUp();
    ASSERT_EQ(run("simulate -q s.toml -o run.h5 --set run.duration=6").code, 0);
  }
  // Runs `args`, sends SIGTERM once the handler is installed; the exit code and output.
  CliResult terminated(const std::string& args) const {
    const std::string shell = "cd '" + dir_.string() + "' && exec '" + GRANWAVE_BINARY + "' " +
                              args + " > out.txt 2> err.txt";
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::execl("/bin/sh", "sh", "-c", shell.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    bool sent = false;
    for (int i = 0; i < 6000 && !sent; ++i) {
      if (catchesSigterm(pid)) sent = ::kill(pid, SIGTERM) == 0;
      if (!sent) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (!sent) ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status), read("out.txt"),
            read("err.txt")};
  }
};

TEST_F(InterruptCli, SigtermEndsHydroFieldsAndExportWith130AndLeavesNothing) {
  for (const std::string& command :
       std::vector<std::string>{"hydro -q s.toml -o h.h5 --set run.duration=60",
                                "fields run.h5 -o f.h5", "export run.h5 -o r.xyz"}) {
    SCOPED_TRACE(command);
    const CliResult r = terminated(command);
    EXPECT_EQ(r.code, 130) << r.err;
    EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(stray("run.h5"), 0);
  }
}

}  // namespace
