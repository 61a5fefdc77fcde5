#include "studies/runner/OrphanedTemporaries.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>

#include "files/SideFiles.hpp"

namespace granwave {

namespace {

// A process that can still write: it exists and is not a zombie. A run killed with its
// study is re-parented, and where PID 1 does not reap (containers) it stays a zombie, which
// kill(pid, 0) still reports as alive; its state letter in /proc/PID/stat (proc(5)) tells.
bool processIsRunning(pid_t pid) {
  if (::kill(pid, 0) != 0 && errno == ESRCH) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;  // no procfs: trust kill()
  const std::size_t close = line.rfind(')');   // the command name may hold spaces and ')'
  if (close == std::string::npos || close + 2 >= line.size()) return true;
  const char state = line[close + 2];
  return state != 'Z' && state != 'X';
}

}  // namespace

void removeOrphanedTemporaries(const std::string& path) {
  const std::filesystem::path p(path);
  const std::filesystem::path dir = p.parent_path().empty() ? "." : p.parent_path();
  const std::string prefix = p.filename().string();
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    long named = 0;
    if (!files::isTemporaryOf(name, prefix, named)) continue;
    const auto pid = static_cast<pid_t>(named);
    if (pid == ::getpid() || processIsRunning(pid)) continue;
    std::filesystem::remove(entry.path(), ec);
  }
}

}  // namespace granwave
