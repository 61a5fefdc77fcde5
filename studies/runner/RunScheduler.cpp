#include "studies/runner/RunScheduler.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <deque>
#include <filesystem>
#include <fstream>
#include <list>
#include <map>
#include <random>
#include <set>
#include <system_error>
#include <thread>

#include "files/OutputPath.hpp"
#include "scene/SceneParser.hpp"
#include "studies/runner/ChildProcess.hpp"
#include "studies/runner/ExitCode.hpp"
#include "studies/runner/InterruptFlag.hpp"
#include "studies/runner/OrphanedTemporaries.hpp"
#include "studies/runner/RemoteWorkers.hpp"
#include "studies/runner/RunClaim.hpp"

namespace granwave {

std::vector<std::string> childArguments(const RunRecord& r, double checkpoint_every) {
  const RunRequest& q = r.request;
  if (q.kind == RunKind::Hydro) return {"hydro", r.scenePath(), "-o", r.hydroPath(), "-q"};
  if (q.kind == RunKind::Lammps) {
    std::vector<std::string> a{"-in", q.deck_path, "-log", "none", "-screen", "none"};
    for (std::size_t i = 0; i + 1 < q.variables.size(); i += 2)
      a.insert(a.end(), {"-var", q.variables[i], q.variables[i + 1]});
    a.insert(a.end(), {"-var", "out", r.lammpsPath()});
    return a;
  }
  std::vector<std::string> a{"simulate", r.scenePath(), "-o", r.runPath(), "-q"};
  if (q.fields)
    a.insert(a.end(), {"--fields", r.fieldsPath(), "--fields-period",
                       std::to_string(q.window_cycles), "--fields-blocks", std::to_string(q.blocks),
                       // The studies read profiles, phases, fronts and states; not the x-z cells.
                       "--fields-without-cells"});
  if (q.fields && q.state_fields) a.push_back("--state-fields");
  if (checkpoint_every > 0)
    a.insert(a.end(), {"--checkpoint-every", fmt::format("{}", checkpoint_every)});
  return a;
}

std::vector<RunRecord> planRecords(const std::vector<RunRequest>& requests, const RunCache& cache) {
  std::vector<RunRecord> records;
  for (const RunRequest& q : requests) records.push_back(cache.record(q));
  return records;
}

namespace {

// The reason a run failed: its error line ("granwave: ..."; stdout and stderr share the log
// and stdout is flushed last), else its last line.
std::string failureReason(const std::string& path) {
  std::ifstream in(path);
  const std::string prefix = "granwave: ";
  std::string line, last, error;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    last = line;
    if (line.rfind(prefix, 0) == 0) error = line.substr(prefix.size());
  }
  return error.empty() ? last : error;
}

// Atomically and checked: a child reading a truncated scene would run the default scene and
// its result would be cached under this one's name.
void writeScene(const RunRecord& r) {
  const std::string tmp = files::temporaryFor(r.scenePath());
  {
    std::ofstream scene(tmp, std::ios::trunc);
    scene << sceneToToml(r.request.scene);
    scene.flush();
    if (!scene)
      throw std::system_error(errno ? errno : EIO, std::generic_category(),
                              r.scenePath() + ": cannot write the run's scene");
  }
  std::filesystem::rename(tmp, r.scenePath());
}

// An outcome the same scene and build would not repeat (runner/ExitCode.hpp): interrupted,
// killed, a file or checkpoint that could not be written or used, could not start.
std::string unfinishedReason(const RunRecord& r, int exit_code) {
  if (exit_code == kExitInterrupted || exit_code == 128 + SIGINT || exit_code == 128 + SIGTERM)
    return "interrupted (not cached)";
  if (exit_code == kExitFileError || exit_code == kExitCheckpointError)
    return failureReason(r.logPath()) + " (not cached)";
  return fmt::format("did not finish: exit code {} (not cached)", exit_code);
}

// A name for one attempt at a run, unique across the processes (and machines) sharing a
// cache: its log is <stem>.<attempt>.log.
std::uint64_t newAttempt() {
  static std::mt19937_64 draw{(static_cast<std::uint64_t>(std::random_device{}()) << 32) ^
                              std::random_device{}()};
  return draw();
}

struct Running {
  std::size_t index;
  ChildProcess child;
};

// One call of runAll: the records in request order, the runs still to start, the children
// running here, and the runs handed to worker ranks.
class Schedule {
 public:
  Schedule(const std::vector<RunRequest>& requests, const RunCache& cache,
           const SchedulerOptions& options, RemoteWorkers* remote)
      : cache_(cache), opt_(options), remote_(remote) {
    for (const RunRequest& q : requests) {
      RunRecord r = cache.record(q);
      const bool duplicate = first_of_stem_.count(r.stem) > 0;
      if (!duplicate) first_of_stem_[r.stem] = records_.size();
      if (!duplicate && !cache.load(r)) pending_.push_back(records_.size());
      records_.push_back(std::move(r));
    }
    total_ = pending_.size();
  }

  std::vector<RunRecord> run() {
    // The handler is in place before the announcement, so a caller that waits for it can
    // interrupt the study at once.
    const auto& interrupt = installInterruptFlag();
    announce();
    while (!pending_.empty() || !waiting_.empty() || !running_.empty() ||
           (remote_ && remote_->busy() > 0)) {
      if (interrupt.load()) stopOnInterrupt();
      retryWaiting();
      launch();
      if (!reap()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (remote_) remote_->stopAll();
    copyDuplicates();
    return std::move(records_);
  }

 private:
  void announce() const {
    const std::size_t reused = first_of_stem_.size() - pending_.size();
    const int workers = remote_ ? remote_->idle() : 0;
    if (!opt_.quiet)
      fmt::print(stderr, "granwave study: {} runs, {} reused from {}, {} to do ({} at a time{})\n",
                 first_of_stem_.size(), reused, cache_.directory(), total_, opt_.jobs,
                 workers ? fmt::format(" here, 1 on each of {} more ranks", workers) : "");
  }

  // The next pending run this study may make: its claim taken (RunClaim.hpp), its scene
  // written, no leftovers of an earlier attempt, and what it had spent before. A run another
  // study is making waits; one it made meanwhile is taken from the cache.
  bool claimNext(std::size_t& i) {
    while (!pending_.empty()) {
      i = pending_.front();
      pending_.pop_front();
      RunRecord& r = records_[i];
      RunClaim claim(r.stem);
      if (!claim.held()) {
        wait(i);
        continue;
      }
      if (cache_.load(r)) {
        reportReused(r);
        continue;
      }
      claims_[i] = std::move(claim);
      r.attempt = fmt::format("{:016x}", attempt_[i] = newAttempt());
      writeScene(r);
      std::filesystem::remove(r.runPath() + ".interrupted");  // left by an earlier interrupt
      removeOrphanedTemporaries(r.stem);  // of any kind of run killed in an earlier study
      if (opt_.checkpoint_every > 0 && opt_.earlier_cost) earlier_cost_[i] = opt_.earlier_cost(r);
      return true;
    }
    return false;
  }

  void wait(std::size_t i) {
    if (!opt_.quiet && announced_waiting_.insert(i).second)
      fmt::print(stderr, "granwave study: {} is being made by another study; waiting for it\n",
                 records_[i].request.label);
    waiting_.push_back(i);
  }

  // Every half second the runs other studies held are tried again.
  void retryWaiting() {
    const auto now = std::chrono::steady_clock::now();
    if (waiting_.empty() || now < next_retry_) return;
    next_retry_ = now + std::chrono::milliseconds(500);
    pending_.insert(pending_.end(), waiting_.begin(), waiting_.end());
    waiting_.clear();
  }

  void reportReused(const RunRecord& r) {
    ++done_;
    if (!opt_.quiet)
      fmt::print(stderr, "granwave study: [{:>3}/{}] {:<44} made by another study{}\n", done_,
                 total_, r.request.label, r.ok ? "" : "  " + r.message);
  }

  void launch() {
    std::size_t i = 0;
    while (remote_ && remote_->idle() > 0 && claimNext(i)) remote_->dispatch(i, attempt_[i]);
    while (static_cast<int>(running_.size()) < opt_.jobs && claimNext(i)) {
      RunRecord& r = records_[i];
      const std::string& program = r.request.kind == RunKind::Lammps ? r.request.program : exe_;
      running_.push_back(
          {i, ChildProcess(program, childArguments(r, opt_.checkpoint_every), r.logPath())});
    }
  }

  // Finished runs, local and remote; false if none finished.
  bool reap() {
    bool reaped = false;
    for (auto it = running_.begin(); it != running_.end();) {
      ChildOutcome out;
      if (!it->child.poll(out)) {
        ++it;
        continue;
      }
      const std::size_t i = it->index;
      it = running_.erase(it);
      reaped = true;
      finish(i, out);
    }
    std::size_t index = 0;
    ChildOutcome remote_out;
    while (remote_ && remote_->poll(index, remote_out)) {
      reaped = true;
      finish(index, remote_out);
    }
    return reaped;
  }

  // One finished run (local or remote): recorded, unless it was interrupted. Only the
  // outcomes the same scene and build would repeat are results and cached.
  void finish(std::size_t i, ChildOutcome out) {
    RunRecord& r = records_[i];
    if (const auto earlier = earlier_cost_.find(i); earlier != earlier_cost_.end()) {
      out.wall += earlier->second.first;
      out.cpu += earlier->second.second;
    }
    r.exit_code = out.exit_code;
    const RunClaim claim = std::move(claims_[i]);  // released once the record is stored
    claims_.erase(i);
    if (!isRunOutcome(out.exit_code)) {
      r.ok = false;
      r.message = unfinishedReason(r, out.exit_code);
      return;
    }
    r.ok = out.exit_code == 0;
    r.message = r.ok ? "" : failureReason(r.logPath());
    r.wall = out.wall;
    r.cpu = out.cpu;
    cache_.store(r);
    ++done_;
    if (opt_.quiet) return;
    const std::string& note = r.request.failure_note;
    fmt::print(stderr, "granwave study: [{:>3}/{}] {:<44} {:7.1f} s{}\n", done_, total_,
               r.request.label, out.wall,
               r.ok ? "" : fmt::format("  {}: {}", note.empty() ? "FAILED" : note, r.message));
  }

  [[noreturn]] void stopOnInterrupt() {
    for (Running& r : running_) r.child.signal(SIGINT);
    running_.clear();  // destructors wait for the children
    if (remote_ && remote_->session().size() > 1) {
      fmt::print(stderr, "granwave: interrupted; finished runs are kept in {}\n",
                 cache_.directory());
      remote_->session().abort(130);  // the workers' children get SIGTERM as they die
    }
    throw StudyInterrupted(fmt::format(
        "interrupted: {} of {} runs finished and kept in {}; run the same command again to "
        "resume",
        done_, total_, cache_.directory()));
  }

  // Duplicates take the outcome of their first occurrence.
  void copyDuplicates() {
    for (RunRecord& r : records_) {
      const RunRecord& first = records_[first_of_stem_[r.stem]];
      if (&first == &r) continue;
      r.ok = first.ok;
      r.exit_code = first.exit_code;
      r.message = first.message;
      r.wall = first.wall;
      r.cpu = first.cpu;
      r.reused = true;
    }
  }

  const RunCache& cache_;
  const SchedulerOptions& opt_;
  RemoteWorkers* remote_;
  const std::string exe_ = selfExecutable();
  std::vector<RunRecord> records_;
  std::map<std::string, std::size_t> first_of_stem_;
  std::deque<std::size_t> pending_;
  // Runs another study sharing the cache holds the claim of, tried again now and then.
  std::deque<std::size_t> waiting_;
  std::set<std::size_t> announced_waiting_;
  std::chrono::steady_clock::time_point next_retry_;
  std::map<std::size_t, RunClaim> claims_;
  std::map<std::size_t, std::uint64_t> attempt_;
  std::list<Running> running_;  // list: children are not move-assignable
  std::map<std::size_t, std::pair<double, double>> earlier_cost_;
  std::size_t total_ = 0, done_ = 0;
};

}  // namespace

std::vector<RunRecord> runAll(const std::vector<RunRequest>& requests, const RunCache& cache,
                              const SchedulerOptions& opt, RemoteWorkers* remote) {
  return Schedule(requests, cache, opt, remote).run();
}

}  // namespace granwave
