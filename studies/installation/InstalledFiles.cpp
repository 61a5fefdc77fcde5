#include "studies/installation/InstalledFiles.hpp"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "studies/runner/ChildProcess.hpp"

namespace granwave {

namespace {

// Where the running executable lives, and whether its file has been replaced since it
// started: a rebuild or reinstall while this process runs makes the kernel name the running
// one "<path> (deleted)", whose directory still holds the installed files. Empty if unknown.
struct RunningExecutable {
  std::filesystem::path path;
  bool replaced = false;
};

RunningExecutable runningExecutable() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::canonical(selfExecutable(), ec);
  if (!ec) return {exe, false};
  std::string target = std::filesystem::read_symlink(selfExecutable(), ec).string();
  const std::string deleted = " (deleted)";
  if (ec || target.size() <= deleted.size() ||
      target.compare(target.size() - deleted.size(), deleted.size(), deleted) != 0)
    return {};
  target.resize(target.size() - deleted.size());
  return {target, true};
}

}  // namespace

std::string installedFile(const std::string& relative) {
  const RunningExecutable exe = runningExecutable();
  const std::filesystem::path bin =
      exe.path.empty() ? std::filesystem::path(".") : exe.path.parent_path();
  // Installed: GNUInstallDirs' DATADIR/granwave as seen from BINDIR (compiled in, relative).
  // In the build tree: build/share/granwave beside build/studies/granwave. The two are the
  // same directory in the default layout.
  std::filesystem::path share = (bin / GRANWAVE_SHARE_FROM_BIN).lexically_normal();
  std::error_code ec;
  if (!std::filesystem::is_directory(share, ec)) share = bin.parent_path() / "share" / "granwave";
  return (share / relative).lexically_normal().string();
}

SourceCommit sourceCommit() {
  // The record beside a replaced executable is the new build's, not this process's.
  const RunningExecutable exe = runningExecutable();
  if (exe.path.empty() || exe.replaced) return {};
  // Written by cmake/SourceCommit.cmake: the commit, then "clean", "dirty" or "unknown".
  std::ifstream in(installedFile("source-commit"));
  std::string commit, state;
  SourceCommit out;
  if (!(in >> commit >> state) || commit == "unknown") return out;
  out.commit = commit;
  out.tree = state == "clean" ? "clean" : state == "dirty" ? "with uncommitted changes" : "unknown";
  return out;
}

}  // namespace granwave
