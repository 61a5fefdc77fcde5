#pragma once
// The files the program ships beside itself (docs/commands.md, "Install"): the report renderer,
// the LAMMPS deck, the source commit it was built from. They are found relative to the running
// executable, <dir of granwave>/../share/granwave/<relative>, both in an installed prefix
// (P/bin/granwave, P/share/granwave/) and in the build tree (build/studies/granwave,
// build/share/granwave/, copied there at configure time), so no absolute source or build path
// is compiled in and an installed prefix can be moved.
#include <string>

namespace granwave {

// The path of a shipped file (it need not exist; the caller says what is missing).
std::string installedFile(const std::string& relative);

// The git commit the running executable was built from and the state of the working tree
// then, as recorded at build time (share/granwave/source-commit by cmake/SourceCommit.cmake)
// and read at run time, so that an installed copy knows it too.
struct SourceCommit {
  std::string commit = "unknown";  // 40 hex digits, or "unknown" (no git checkout, no record)
  std::string tree = "unknown";    // "clean", "with uncommitted changes", "unknown"
};
SourceCommit sourceCommit();

}  // namespace granwave
