#pragma once
// Study runs on other MPI ranks: `mpirun -n P granwave study FILE` makes rank 0 the
// coordinator (it runs the scheduler, runs one run itself at a time, and hands the others out
// one by one as ranks become free: dynamic load balancing, since scenes differ in cost by
// orders of magnitude) and ranks 1..P-1 workers (each runs what it is given as a child process
// and reports the outcome). All ranks share the file system (the run cache); rank 0 alone
// writes records, results.h5 and the report. Without MPI (or outside mpirun) there is one rank
// and the same study uses local child processes only.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "studies/runner/ChildProcess.hpp"
#include "studies/runner/RunRequest.hpp"

namespace granwave {

// MPI_Init / MPI_Finalize when the process was started by mpirun (OpenMPI or PMIx
// environment), else nothing: a single rank.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Ends every rank at once (the coordinator was interrupted).
  [[noreturn]] void abort(int code) const;

 private:
  bool initialized_ = false;
  int rank_ = 0, size_ = 1;
};

// The coordinator's view of the worker ranks.
class RemoteWorkers {
 public:
  explicit RemoteWorkers(const MpiSession& mpi);
  int idle() const { return static_cast<int>(idle_.size()); }
  int busy() const { return busy_; }
  // Hands run `index` to an idle rank; its log is named for `attempt` (RunRecord::attempt).
  void dispatch(std::size_t index, std::uint64_t attempt);
  // A finished remote run, if any (non-blocking).
  bool poll(std::size_t& index, ChildOutcome& outcome);
  void stopAll();  // every worker leaves its loop (all must be idle)
  const MpiSession& session() const { return *mpi_; }

 private:
  const MpiSession* mpi_;
  std::vector<int> idle_;
  int busy_ = 0;
};

// A worker rank's loop: run each index it is given (the child arguments from `arguments`)
// until told to stop.
void workerLoop(const MpiSession& mpi, const std::vector<RunRecord>& records,
                const std::function<std::vector<std::string>(const RunRecord&)>& arguments);

}  // namespace granwave
