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

SourceCommit sourceCommit() {
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
