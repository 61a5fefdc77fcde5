#pragma once
// `granwave export RUN.h5 [-o OUT] [--format F] [--every K]`: the trajectory of a run file in
// a format the field's viewers and analysis tools read (docs/commands.md, "Viewers"): extended
// XYZ (ASE, OVITO), GSD (HOOMD-blue, OVITO, MDAnalysis), LAMMPS dump (LAMMPS, OVITO, ASE,
// MDAnalysis) and H5MD in nm (MDAnalysis, whose H5MD reader refuses the run file's metres).
// The writers and their layouts are in exports/.
#include <string>

namespace CLI {
class App;
}

namespace granwave {

struct ExportOptions {
  std::string run_path;
  std::string output;  // default: <run stem> with the format's extension
  std::string format;  // empty: from the output's extension, else extxyz
  int every = 1;       // every K-th frame
};

void addExportCommand(CLI::App& app, ExportOptions& options);
int runExport(const ExportOptions& options);

}  // namespace granwave
