#pragma once
// `granwave export RUN.h5 [-o OUT] [--format extxyz] [--every K]`: the trajectory of a run file
// in a format the field's viewers and analysis tools read (docs/commands.md, "Viewers"). The
// run file itself is H5MD in SI units, which MDAnalysis's H5MD reader does not accept (it knows
// nm, Angstrom, pm and fm only); extended XYZ is read by ASE and OVITO.
#include <string>

namespace CLI {
class App;
}

namespace granwave {

struct ExportOptions {
  std::string run_path;
  std::string output;  // default: <run>.extxyz beside the run file's stem
  std::string format = "extxyz";
  int every = 1;  // every K-th frame
};

void addExportCommand(CLI::App& app, ExportOptions& options);
int runExport(const ExportOptions& options);

}  // namespace granwave
