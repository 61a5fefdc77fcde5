#pragma once
// One child process of the study runner: `granwave simulate` or `granwave hydro` on a cached
// scene, with stdout and stderr sent to a log file. Runs go to child processes, not threads,
// because the HDF5 library Debian ships is not thread-safe and because a crash or a collapse
// of one scene must not take the study down with it.
#include <sys/types.h>

#include <string>
#include <vector>

namespace granwave {

struct ChildOutcome {
  int exit_code = -1;  // the child's exit status; 128 + signal if it was killed
  double wall = 0;     // s, from start to exit
  double cpu = 0;      // s, user + system time of the child
};

class ChildProcess {
 public:
  // Starts `program args...` with stdin from /dev/null and stdout+stderr appended to log; the
  // child gets SIGTERM if this process dies. Throws std::runtime_error if fork fails (an exec
  // failure shows as exit code 127).
  ChildProcess(const std::string& program, const std::vector<std::string>& args,
               const std::string& log_path);
  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess& operator=(ChildProcess&&) = delete;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  // Waits for a child that is still running (the study was aborted by an error).
  ~ChildProcess();

  pid_t pid() const { return pid_; }
  // Non-blocking: true (and the outcome filled) once the child has exited.
  bool poll(ChildOutcome& outcome);
  // Forwards a signal (the study was interrupted).
  void signal(int sig) const;

 private:
  pid_t pid_ = -1;
  double started_ = 0;  // steady clock, s
};

// The running executable, for starting subcommands of itself: "/proc/self/exe", which names
// the very file this process runs even if the build directory is relinked meanwhile.
std::string selfExecutable();

}  // namespace granwave
