#pragma once
// Runs a study's requests as child processes of this executable (`granwave simulate` /
// `granwave hydro`), `jobs` at a time, skipping those the cache already holds. Results come
// back in request order. Identical requests (same cache entry) run once.
#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "studies/runner/RunCache.hpp"
#include "studies/runner/RunRequest.hpp"

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
  // study continues its unfinished runs where they stood (run_files/RunCheckpoint.hpp).
  double checkpoint_every = 0;
  // With checkpoints: the cost (wall, CPU seconds) a run had spent before the checkpoint it
  // will continue from, added to the cost measured now. The caller knows the run's files;
  // the scheduler does not open them.
  std::function<std::pair<double, double>(const RunRecord&)> earlier_cost;
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
