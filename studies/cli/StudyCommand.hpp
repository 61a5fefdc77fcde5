#pragma once
// `granwave study STUDY.toml [-o OUTDIR] [--cache DIR] [-j JOBS] [-q]`: checks the study file, runs
// what the cache does not hold (OUTDIR/runs), analyses, and writes OUTDIR/results.h5 and
// OUTDIR/report.html (drawn by studies/report/render_report.py with Debian's matplotlib).
#include "studies/study_run/StudyRun.hpp"

namespace CLI {
class App;
}

namespace granwave {

// The options are those of the study run (studies/study_run/StudyRun.hpp).
using StudyOptions = StudyRunOptions;

void addStudyCommand(CLI::App& app, StudyOptions& options);
// Under mpirun, rank 0 coordinates and writes the outputs; the other ranks run what they are
// given and return 0 (RemoteWorkers.hpp).
int runStudy(const StudyOptions& options, const MpiSession& mpi);

}  // namespace granwave
