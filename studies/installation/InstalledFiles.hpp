#pragma once
// The files the program ships beside itself (docs/commands.md, "Install"): the report renderer,
// the LAMMPS deck, the study files and scenes, the source commit it was built from. They are
// found relative to the running executable: in an installed prefix at the path from BINDIR to
// DATADIR/granwave (P/bin/granwave, P/share/granwave/ by default), in the build tree at
// build/share/granwave/ beside build/studies/granwave (copied there at configure time). No
// absolute source or build path is compiled in, so an installed prefix can be moved.
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
