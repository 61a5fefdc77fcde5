#include "studies/RunScheduler.hpp"

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
#include <system_error>
#include <thread>

#include "scene/SceneParser.hpp"
#include "studies/ChildProcess.hpp"
#include "studies/ExitCode.hpp"
#include "studies/InterruptFlag.hpp"
#include "studies/RemoteWorkers.hpp"
#include "studies/RunCheckpoint.hpp"

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
    a.insert(a.end(),
             {"--fields", r.fieldsPath(), "--fields-period", std::to_string(q.window_cycles),
              "--fields-blocks", std::to_string(q.blocks)});
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

struct Running {
  std::size_t index;
  ChildProcess child;
};

}  // namespace

std::vector<RunRecord> runAll(const std::vector<RunRequest>& requests, const RunCache& cache,
                              const SchedulerOptions& opt, RemoteWorkers* remote) {
  std::vector<RunRecord> records;
  std::map<std::string, std::size_t> first_of_stem;
  std::deque<std::size_t> pending;
  for (const RunRequest& q : requests) {
    RunRecord r = cache.record(q);
    const bool duplicate = first_of_stem.count(r.stem) > 0;
    if (!duplicate) first_of_stem[r.stem] = records.size();
    if (!duplicate && !cache.load(r)) pending.push_back(records.size());
    records.push_back(std::move(r));
  }
  const std::size_t reused = first_of_stem.size() - pending.size();
  const std::size_t total = pending.size();
  const int workers = remote ? remote->idle() : 0;
  if (!opt.quiet)
    fmt::print(stderr, "granwave study: {} runs, {} reused from {}, {} to do ({} at a time{})\n",
               first_of_stem.size(), reused, cache.directory(), total, opt.jobs,
               workers ? fmt::format(" here, 1 on each of {} more ranks", workers) : "");

  const std::string exe = selfExecutable();
  const auto& interrupt = installInterruptFlag();
  std::list<Running> running;  // list: children are not move-assignable
  // Atomically and checked: a child reading a truncated scene would run the default scene
  // and its result would be cached under this one's name.
  auto writeScene = [](const RunRecord& r) {
    const std::string tmp = r.scenePath() + ".tmp-" + std::to_string(::getpid());
    {
      std::ofstream scene(tmp, std::ios::trunc);
      scene << sceneToToml(r.request.scene);
      scene.flush();
      if (!scene)
        throw std::system_error(errno ? errno : EIO, std::generic_category(),
                                r.scenePath() + ": cannot write the run's scene");
    }
    std::filesystem::rename(tmp, r.scenePath());
  };
  // A run continued from a checkpoint costs what it had spent before, too.
  std::map<std::size_t, std::pair<double, double>> earlier_cost;
  auto start = [&](std::size_t i) {
    RunRecord& r = records[i];
    writeScene(r);
    std::filesystem::remove(r.runPath() + ".interrupted");  // left by an earlier interrupt
    removeOrphanedTemporaries(r.stem);  // of any kind of run killed in an earlier study
    if (r.request.kind == RunKind::Particles && opt.checkpoint_every > 0)
      earlier_cost[i] = checkpointedCost(r.runPath());
  };
  // One finished run (local or remote): record it, unless it was interrupted.
  std::size_t done = 0;
  auto finish = [&](RunRecord& r, ChildOutcome out) {
    const auto earlier = earlier_cost.find(static_cast<std::size_t>(&r - records.data()));
    if (earlier != earlier_cost.end()) {
      out.wall += earlier->second.first;
      out.cpu += earlier->second.second;
    }
    // Only the outcomes the same scene and build would repeat are results and cached
    // (studies/ExitCode.hpp). Anything else (interrupted, killed, a file or checkpoint that
    // could not be written or used, could not start) is tried again next time.
    if (!isRunOutcome(out.exit_code)) {
      r.ok = false;
      r.exit_code = out.exit_code;
      if (out.exit_code == kExitInterrupted || out.exit_code == 128 + SIGINT ||
          out.exit_code == 128 + SIGTERM)
        r.message = "interrupted (not cached)";
      else if (out.exit_code == kExitFileError || out.exit_code == kExitCheckpointError)
        r.message = failureReason(r.logPath()) + " (not cached)";
      else
        r.message = fmt::format("did not finish: exit code {} (not cached)", out.exit_code);
      return;
    }
    r.ok = out.exit_code == 0;
    r.exit_code = out.exit_code;
    r.message = r.ok ? "" : failureReason(r.logPath());
    r.wall = out.wall;
    r.cpu = out.cpu;
    cache.store(r);
    ++done;
    if (!opt.quiet)
      fmt::print(stderr, "granwave study: [{:>3}/{}] {:<44} {:7.1f} s{}\n", done, total,
                 r.request.label, out.wall, r.ok ? "" : "  FAILED: " + r.message);
  };
  while (!pending.empty() || !running.empty() || (remote && remote->busy() > 0)) {
    if (interrupt.load()) {
      for (Running& r : running) r.child.signal(SIGINT);
      running.clear();  // destructors wait for the children
      if (remote && remote->session().size() > 1) {
        fmt::print(stderr, "granwave: interrupted; finished runs are kept in {}\n",
                   cache.directory());
        remote->session().abort(130);  // the workers' children get SIGTERM as they die
      }
      throw StudyInterrupted(fmt::format(
          "interrupted: {} of {} runs finished and kept in {}; run the same command again to "
          "resume",
          done, total, cache.directory()));
    }
    while (!pending.empty() && remote && remote->idle() > 0) {
      const std::size_t i = pending.front();
      pending.pop_front();
      start(i);
      remote->dispatch(i);
    }
    while (!pending.empty() && static_cast<int>(running.size()) < opt.jobs) {
      const std::size_t i = pending.front();
      pending.pop_front();
      start(i);
      RunRecord& r = records[i];
      std::filesystem::remove(r.logPath());
      const std::string& program = r.request.kind == RunKind::Lammps ? r.request.program : exe;
      running.push_back(
          {i, ChildProcess(program, childArguments(r, opt.checkpoint_every), r.logPath())});
    }
    bool reaped = false;
    for (auto it = running.begin(); it != running.end();) {
      ChildOutcome out;
      if (!it->child.poll(out)) {
        ++it;
        continue;
      }
      RunRecord& r = records[it->index];
      it = running.erase(it);
      reaped = true;
      finish(r, out);
    }
    std::size_t index = 0;
    ChildOutcome remote_out;
    while (remote && remote->poll(index, remote_out)) {
      reaped = true;
      finish(records[index], remote_out);
    }
    if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (remote) remote->stopAll();
  // Duplicates take the outcome of their first occurrence.
  for (RunRecord& r : records) {
    const RunRecord& first = records[first_of_stem[r.stem]];
    if (&first == &r) continue;
    r.ok = first.ok;
    r.exit_code = first.exit_code;
    r.message = first.message;
    r.wall = first.wall;
    r.cpu = first.cpu;
    r.reused = true;
  }
  return records;
}

}  // namespace granwave
