#include "studies/runner/RemoteWorkers.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>

#ifdef GRANWAVE_HAVE_MPI
#include <mpi.h>
#endif

namespace granwave {

namespace {

[[maybe_unused]] constexpr int kTagWork = 1, kTagDone = 2;
[[maybe_unused]] constexpr unsigned long long kStop = ~0ull;  // the work message's "leave"

bool launchedByMpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK");
}

// Only `granwave study` uses MPI. Its runs (`granwave simulate` / `hydro` child processes)
// inherit mpirun's environment and must not join the job.
bool isStudy(int argc, char** argv) { return argc > 1 && std::string(argv[1]) == "study"; }

}  // namespace

#ifdef GRANWAVE_HAVE_MPI

MpiSession::MpiSession(int& argc, char**& argv) {
  if (!launchedByMpirun() || !isStudy(argc, argv)) return;
  MPI_Init(&argc, &argv);
  initialized_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  if (initialized_) MPI_Finalize();
}

void MpiSession::abort(int code) const {
  if (initialized_) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

RemoteWorkers::RemoteWorkers(const MpiSession& mpi) : mpi_(&mpi) {
  for (int r = 1; r < mpi.size(); ++r) idle_.push_back(r);
}

void RemoteWorkers::dispatch(std::size_t index, std::uint64_t attempt) {
  if (idle_.empty()) throw std::logic_error("no idle worker rank");
  const unsigned long long work[2] = {index, attempt};
  MPI_Send(work, 2, MPI_UNSIGNED_LONG_LONG, idle_.back(), kTagWork, MPI_COMM_WORLD);
  idle_.pop_back();
  ++busy_;
}

bool RemoteWorkers::poll(std::size_t& index, ChildOutcome& outcome) {
  if (busy_ == 0) return false;
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, kTagDone, MPI_COMM_WORLD, &flag, &status);
  if (!flag) return false;
  double msg[4];
  MPI_Recv(msg, 4, MPI_DOUBLE, status.MPI_SOURCE, kTagDone, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  index = static_cast<std::size_t>(msg[0]);
  outcome.exit_code = static_cast<int>(msg[1]);
  outcome.wall = msg[2];
  outcome.cpu = msg[3];
  idle_.push_back(status.MPI_SOURCE);
  --busy_;
  return true;
}

void RemoteWorkers::stopAll() {
  const unsigned long long stop[2] = {kStop, 0};
  for (int r : idle_) MPI_Send(stop, 2, MPI_UNSIGNED_LONG_LONG, r, kTagWork, MPI_COMM_WORLD);
  idle_.clear();
}

void workerLoop(const MpiSession&, const std::vector<RunRecord>& records,
                const std::function<std::vector<std::string>(const RunRecord&)>& arguments) {
  const std::string exe = selfExecutable();
  for (;;) {
    unsigned long long work[2] = {kStop, 0};
    MPI_Recv(work, 2, MPI_UNSIGNED_LONG_LONG, 0, kTagWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (work[0] == kStop) return;
    const std::size_t i = work[0];
    ChildOutcome out;
    out.exit_code = 127;  // reported if the run cannot even be started
    try {
      RunRecord r = records.at(i);
      r.attempt = fmt::format("{:016x}", work[1]);
      ChildProcess child(r.request.kind == RunKind::Lammps ? r.request.program : exe, arguments(r),
                         r.logPath());
      while (!child.poll(out)) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    } catch (const std::exception&) {
      // Always answer: rank 0 waits for every run it handed out.
    }
    const double msg[4] = {static_cast<double>(i), static_cast<double>(out.exit_code), out.wall,
                           out.cpu};
    MPI_Send(msg, 4, MPI_DOUBLE, 0, kTagDone, MPI_COMM_WORLD);
  }
}

#else  // a build without MPI: one rank, never any workers

MpiSession::MpiSession(int& argc, char**& argv) {
  if (launchedByMpirun() && isStudy(argc, argv) && std::getenv("OMPI_COMM_WORLD_SIZE") &&
      std::string(std::getenv("OMPI_COMM_WORLD_SIZE")) != "1") {
    std::fputs(
        "granwave: this build has no MPI (libopenmpi-dev was missing at configure time); run "
        "it without mpirun: it uses all local cores\n",
        stderr);
    std::exit(2);
  }
}
MpiSession::~MpiSession() = default;
void MpiSession::abort(int code) const { std::exit(code); }
RemoteWorkers::RemoteWorkers(const MpiSession& mpi) : mpi_(&mpi) {}
void RemoteWorkers::dispatch(std::size_t, std::uint64_t) {
  throw std::logic_error("no worker ranks");
}
bool RemoteWorkers::poll(std::size_t&, ChildOutcome&) { return false; }
void RemoteWorkers::stopAll() {}
void workerLoop(const MpiSession&, const std::vector<RunRecord>&,
                const std::function<std::vector<std::string>(const RunRecord&)>&) {}

#endif

}  // namespace granwave
