#include "studies/framework/InstalledFiles.hpp"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "studies/runner/ChildProcess.hpp"

namespace granwave {

std::string installedFile(const std::string& relative) {
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::canonical(selfExecutable(), ec);
  if (ec) {
    // A rebuild or reinstall while this process runs replaces its file: the kernel then names
    // the running one "<path> (deleted)", whose directory still holds the installed files.
    std::error_code link_ec;
    std::string target = std::filesystem::read_symlink(selfExecutable(), link_ec).string();
    const std::string deleted = " (deleted)";
    if (!link_ec && target.size() > deleted.size() &&
        target.compare(target.size() - deleted.size(), deleted.size(), deleted) == 0) {
      target.resize(target.size() - deleted.size());
      exe = target;
      ec.clear();
    }
  }
  const std::filesystem::path bin = ec ? std::filesystem::path(".") : exe.parent_path();
  return (bin.parent_path() / "share" / "granwave" / relative).lexically_normal().string();
}

SourceCommit sourceCommit() {
  // The record beside a replaced executable is the new build's, not this process's.
  std::error_code ec;
  if (std::filesystem::canonical(selfExecutable(), ec).empty() || ec) return {};
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
