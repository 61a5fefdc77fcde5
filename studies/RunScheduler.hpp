#pragma once
// Runs a study's requests as child processes of this executable (`granwave simulate` /
// `granwave hydro`), `jobs` at a time, skipping those the cache already holds. Results come
// back in request order. Identical requests (same cache entry) run once.
#include <stdexcept>
#include <vector>

#include "studies/RunCache.hpp"
#include "studies/RunRequest.hpp"

namespace granwave {

// The study was interrupted (SIGINT/SIGTERM): finished runs are kept in the cache.
class StudyInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SchedulerOptions {
  int jobs = 1;  // local runs at a time
  bool quiet = false;
  // Particle runs checkpoint every this many seconds of wall time (0 = never), so a killed
  // study continues its unfinished runs where they stood (studies/RunCheckpoint.hpp).
  double checkpoint_every = 0;
};

class RemoteWorkers;

// `remote` (may be null): worker ranks that take runs too (RemoteWorkers.hpp).
std::vector<RunRecord> runAll(const std::vector<RunRequest>& requests, const RunCache& cache,
                              const SchedulerOptions& options, RemoteWorkers* remote = nullptr);

// The records of a plan in request order without running anything (worker ranks).
std::vector<RunRecord> planRecords(const std::vector<RunRequest>& requests, const RunCache& cache);

// The command line of the child process that makes a run.
std::vector<std::string> childArguments(const RunRecord& record, double checkpoint_every = 0);

}  // namespace granwave
