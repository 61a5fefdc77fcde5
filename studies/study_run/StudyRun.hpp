#pragma once
// One study as `granwave study` makes it (docs/studies.md): its runs made where the cache does
// not hold them (several at a time as child processes, or over MPI ranks), follow-up rounds
// while a verdict is open (each announced on stderr with its reason and expected time:
// FollowUpProgress.hpp), then results.h5 (the study's numbers and report, the runs' cost, the
// provenance; atomically) and the report page drawn by studies/report/render_report.py.
#include <string>

#include "studies/contract/Study.hpp"
#include "studies/runner/RemoteWorkers.hpp"

namespace granwave {

struct StudyRunOptions {
  std::string study_path;
  std::string output;             // default: the study file's stem, in the working directory
  std::string cache;              // run cache; default OUTDIR/runs (studies may share one)
  int jobs = 0;                   // 0 = number of cores
  double checkpoint_every = 300;  // s of wall time between a particle run's checkpoints
  bool quiet = false;
  bool no_report = false;  // results.h5 only (no Python needed)
  bool plan = false;       // list the runs and the cache's share of them; run and write nothing
};

// --plan: every run of the study's first round on stdout (method, cached or to do, label) and
// their count; nothing is run, made or written. Returns the exit code.
int printStudyPlan(const StudyRunOptions& options, const Study& study);

// `study` was made from `file`, whose keys are all read. `file_jobs` is its [study] jobs.
// Under mpirun rank 0 coordinates and writes the outputs; the other ranks run what they are
// given and return 0 (RemoteWorkers.hpp). Returns the exit code; throws on errors.
int runStudyPlan(const StudyRunOptions& options, const StudyFile& file, const Study& study,
                 int file_jobs, const MpiSession& mpi, const std::string& program_version);

}  // namespace granwave
