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

// The git commit the running executable was built from and whether the working tree had
// uncommitted changes, as recorded at build time (share/granwave/source-commit): e.g.
// "3f2a9c1d0e...", "3f2a9c1d0e... (with uncommitted changes)", or "unknown" when the build
// was not made from a git checkout or the record is missing.
std::string sourceCommit();

}  // namespace granwave
