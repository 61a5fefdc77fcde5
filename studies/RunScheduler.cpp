#include "studies/RunScheduler.hpp"

#include <fmt/format.h>

#include <chrono>
#include <csignal>
#include <deque>
#include <filesystem>
#include <fstream>
#include <list>
#include <map>
#include <thread>

#include "scene/SceneParser.hpp"
#include "studies/ChildProcess.hpp"
#include "studies/InterruptFlag.hpp"

namespace granwave {

namespace {

std::vector<std::string> childArguments(const RunRecord& r) {
  const RunRequest& q = r.request;
  if (q.kind == RunKind::Hydro) return {"hydro", r.scenePath(), "-o", r.hydroPath(), "-q"};
  if (!q.fields) return {"simulate", r.scenePath(), "-o", r.runPath(), "-q"};
  return {"simulate",
          r.scenePath(),
          "-o",
          r.runPath(),
          "--fields",
          r.fieldsPath(),
          "--fields-period",
          std::to_string(q.window_cycles),
          "--fields-blocks",
          std::to_string(q.blocks),
          "-q"};
}

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
                              const SchedulerOptions& opt) {
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
  if (!opt.quiet)
    fmt::print(stderr, "granwave study: {} runs, {} reused from {}, {} to do ({} at a time)\n",
               first_of_stem.size(), reused, cache.directory(), total, opt.jobs);

  const std::string exe = selfExecutable();
  const auto& interrupt = installInterruptFlag();
  std::list<Running> running;  // list: children are not move-assignable
  std::size_t done = 0;
  while (!pending.empty() || !running.empty()) {
    if (interrupt.load()) {
      for (Running& r : running) r.child.signal(SIGINT);
      running.clear();  // destructors wait for the children
      throw StudyInterrupted(fmt::format(
          "interrupted: {} of {} runs finished and kept in {}; run the same command again to "
          "resume",
          done, total, cache.directory()));
    }
    while (!pending.empty() && static_cast<int>(running.size()) < opt.jobs) {
      RunRecord& r = records[pending.front()];
      pending.pop_front();
      {
        std::ofstream scene(r.scenePath());
        scene << sceneToToml(r.request.scene);
      }
      std::filesystem::remove(r.logPath());
      std::filesystem::remove(r.runPath() + ".interrupted");  // left by an earlier interrupt
      running.push_back({static_cast<std::size_t>(&r - records.data()),
                         ChildProcess(exe, childArguments(r), r.logPath())});
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
      if (out.exit_code == 130 || out.exit_code == 128 + SIGINT || out.exit_code == 128 + SIGTERM ||
          out.exit_code == 128 + SIGKILL) {
        // Interrupted or killed from outside: not a result, so nothing is cached and the
        // next invocation runs it again.
        r.ok = false;
        r.exit_code = out.exit_code;
        r.message = "interrupted (not cached)";
        continue;
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
    }
    if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
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
