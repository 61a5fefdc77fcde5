#include "studies/framework/InstalledFiles.hpp"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "studies/runner/ChildProcess.hpp"

namespace granwave {

std::string installedFile(const std::string& relative) {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::canonical(selfExecutable(), ec);
  const std::filesystem::path bin = ec ? std::filesystem::path(".") : exe.parent_path();
  return (bin.parent_path() / "share" / "granwave" / relative).lexically_normal().string();
}

std::string sourceCommit() {
  // Written by cmake/SourceCommit.cmake: the commit, then "clean", "dirty" or "unknown".
  std::ifstream in(installedFile("source-commit"));
  std::string commit, state;
  if (!(in >> commit >> state) || commit == "unknown") return "unknown";
  return state == "dirty" ? commit + " (with uncommitted changes)" : commit;
}

}  // namespace granwave
