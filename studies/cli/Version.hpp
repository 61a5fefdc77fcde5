#pragma once
// Program version, from the project() call in CMakeLists.txt.
#include <string>

namespace granwave {

inline constexpr const char* kVersion = GRANWAVE_VERSION;

// What `granwave --version` prints: "granwave 0.1.0 (source commit <40 hex digits>, clean)",
// the commit as recorded at build time (studies/installation/InstalledFiles.hpp), "with
// uncommitted changes" if the tree had them, "source commit unknown" outside a git checkout.
std::string versionLine();

}  // namespace granwave
