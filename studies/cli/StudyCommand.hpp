#pragma once
// `granwave study STUDY.toml [-o OUTDIR] [--cache DIR] [-j JOBS] [-q]`: checks the study file, runs
// what the cache does not hold (OUTDIR/runs), analyses, and writes OUTDIR/results.h5 and
// OUTDIR/report.html (drawn by studies/report/render_report.py with Debian's matplotlib).
#include <string>

namespace CLI {
class App;
}

namespace granwave {

struct StudyOptions {
  std::string study_path;
  std::string output;             // default: the study file's stem, in the working directory
  std::string cache;              // run cache; default OUTDIR/runs (studies may share one)
  int jobs = 0;                   // 0 = number of cores
  double checkpoint_every = 300;  // s of wall time between a particle run's checkpoints
  bool quiet = false;
  bool no_report = false;  // results.h5 only (no Python needed)
};

class MpiSession;

void addStudyCommand(CLI::App& app, StudyOptions& options);
// Under mpirun, rank 0 coordinates and writes the outputs; the other ranks run what they are
// given and return 0 (RemoteWorkers.hpp).
int runStudy(const StudyOptions& options, const MpiSession& mpi);

}  // namespace granwave
