#include "studies/cli/Version.hpp"

#include <fmt/format.h>

#include "studies/installation/InstalledFiles.hpp"

namespace granwave {

std::string versionLine() {
  const SourceCommit source = sourceCommit();
  if (source.commit == "unknown")
    return fmt::format("granwave {} (source commit unknown)", kVersion);
  return fmt::format("granwave {} (source commit {}, {})", kVersion, source.commit, source.tree);
}

}  // namespace granwave
