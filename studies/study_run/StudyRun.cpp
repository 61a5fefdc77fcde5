#include "studies/study_run/StudyRun.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>
#include <utility>

#include "files/OutputPath.hpp"
#include "h5/AtomicFile.hpp"
#include "studies/installation/InstalledFiles.hpp"
#include "studies/report/ReportWriter.hpp"
#include "studies/run_files/RunCheckpoint.hpp"
#include "studies/runner/ChildProcess.hpp"
#include "studies/runner/InterruptFlag.hpp"
#include "studies/runner/RunCache.hpp"
#include "studies/runner/RunScheduler.hpp"
#include "studies/study_run/FollowUpProgress.hpp"
#include "studies/study_run/RunCosts.hpp"

namespace granwave {

namespace {

std::string reportScript() {
  if (const char* env = std::getenv("GRANWAVE_REPORT_SCRIPT")) return env;
  return installedFile("report/render_report.py");
}

void renderReport(const std::string& results, const std::string& html, const std::string& log) {
  const char* env = std::getenv("GRANWAVE_PYTHON");
  const std::string python = env ? env : "/usr/bin/python3";
  if (!std::filesystem::exists(python))
    throw std::runtime_error(
        fmt::format("{} not found: the report needs Debian's python3-matplotlib and python3-h5py "
                    "(results are in {}; use --no-report to skip the page)",
                    python, results));
  const std::string script = reportScript();
  if (!std::filesystem::exists(script))
    throw std::runtime_error(fmt::format(
        "the report renderer {} is missing (it is installed with granwave under "
        "share/granwave/report; GRANWAVE_REPORT_SCRIPT names another; results are in {})",
        script, results));
  std::filesystem::remove(log);
  ChildProcess child(python, {script, results, html}, log);
  ChildOutcome out;
  while (!child.poll(out)) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  if (out.exit_code != 0) {
    std::ifstream in(log);
    std::string line, last;
    while (std::getline(in, line))
      if (!line.empty()) last = line;
    throw std::runtime_error(fmt::format("drawing the report failed: {} (log: {})", last, log));
  }
}

// A run that did not finish (killed, could not start) is not a result: no results.h5.
void requireFinished(const RunSet& runs, const std::string& cache_dir) {
  int unfinished = 0;
  std::string example;
  for (const RunRecord& r : runs.all())
    if (!r.ok && r.message.find("(not cached)") != std::string::npos) {
      ++unfinished;
      if (example.empty()) example = r.request.label + ": " + r.message;
    }
  if (unfinished > 0)
    throw std::runtime_error(fmt::format(
        "{} run(s) did not finish ({}); finished runs are kept in {}: run the same command "
        "again",
        unfinished, example, cache_dir));
}

// results.h5 (layout: docs/studies.md), atomically: the study's numbers and report, the runs'
// cost, the provenance. An interrupt during the analysis commits nothing; the runs stay cached.
void writeResults(const std::string& path, const Study& study, const StudyFile& file,
                  const RunSet& runs, const std::string& build_id,
                  const std::string& program_version) {
  h5::AtomicFile af(path);
  h5::File& f = af.file();
  Report report;
  report.title = study.title();
  f.createGroup("/results");
  study.analyse(runs, f, report);
  writeRunCosts(runs, f, report);
  f.writeStringAttribute("/", "format", "granwave-study-1");
  f.writeStringAttribute("/", "study", file.kind());
  f.writeStringAttribute("/", "title", report.title);
  f.writeStringAttribute("/", "summary", report.summary);
  f.writeStringAttribute("/", "granwave_version", program_version);
  f.writeStringAttribute("/", "build_id", build_id);
  const SourceCommit source = sourceCommit();
  f.writeStringAttribute("/", "source_commit", source.commit);
  f.writeStringAttribute("/", "source_tree", source.tree);
  f.writeStringDataset("/study_file", file.text());
  writeReport(f, report);
  if (installInterruptFlag().load())
    throw StudyInterrupted("interrupted during the analysis; run the same command again");
  af.commit();
}

// Runs at a time: -j, else [study] jobs, else one per rank under mpirun, else every core.
int jobsOf(const StudyRunOptions& opt, int file_jobs, const MpiSession& mpi) {
  int jobs = opt.jobs > 0 ? opt.jobs : file_jobs;
  // Under mpirun each rank is meant to have a core of its own: one run at a time per rank.
  if (jobs <= 0 && mpi.size() > 1) jobs = 1;
  if (jobs <= 0) jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return jobs;
}

// -o (default: the study file's stem in the working directory) and --cache (default OUTDIR/runs).
std::pair<std::string, std::string> outputAndCacheDirectories(const StudyRunOptions& opt) {
  std::string outdir = opt.output;
  if (outdir.empty()) outdir = std::filesystem::path(opt.study_path).stem().string();
  std::string cache_dir =
      opt.cache.empty() ? (std::filesystem::path(outdir) / "runs").string() : opt.cache;
  return {outdir, cache_dir};
}

// An output counts as made if HDF5 opens it (RunCache.hpp: else the run is made again).
bool readableOutput(const std::string& path) {
  try {
    h5::File::openReadOnly(path);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

int printStudyPlan(const StudyRunOptions& opt, const Study& study) {
  const std::string cache_dir = outputAndCacheDirectories(opt).second;
  const RunCache cache = RunCache::lookOnly(cache_dir, buildIdentity(), readableOutput);
  std::set<std::string> distinct, held;
  int particles = 0, hydro = 0, lammps = 0;
  for (const RunRequest& q : study.plan()) {
    RunRecord r = cache.record(q);
    if (!distinct.insert(r.stem).second) continue;  // the same run under a second label
    // A failed run's record is reused as a study reuses it (its failure is reported).
    const bool cached = cache.load(r);
    if (cached) held.insert(r.stem);
    (q.kind == RunKind::Particles ? particles : q.kind == RunKind::Hydro ? hydro : lammps)++;
    fmt::print("{:<9}  {:<15}  {}\n", runKindName(q.kind),
               !cached ? "to do"
               : r.ok  ? "cached"
                       : "cached (failed)",
               q.label);
  }
  fmt::print("study           {} ({})\n", opt.study_path, study.title());
  fmt::print("runs            {} ({} particles, {} hydro, {} LAMMPS); {} held by {}, {} to do\n",
             distinct.size(), particles, hydro, lammps, held.size(), cache_dir,
             distinct.size() - held.size());
  fmt::print("follow-ups      decided from the runs' results, after them (none listed here)\n");
  return 0;
}

int runStudyPlan(const StudyRunOptions& opt, const StudyFile& file, const Study& study,
                 int file_jobs, const MpiSession& mpi, const std::string& program_version) {
  const int jobs = jobsOf(opt, file_jobs, mpi);
  std::vector<RunRequest> plan = study.plan();

  const auto [outdir, cache_dir] = outputAndCacheDirectories(opt);
  // Both checked before either is made: a refused --cache leaves no empty output directory.
  files::requireOutputDirectory(outdir, "-o");
  if (!opt.cache.empty()) files::requireOutputDirectory(cache_dir, "--cache");
  std::filesystem::create_directories(outdir);
  const std::string results = (std::filesystem::path(outdir) / "results.h5").string();
  const std::string html = (std::filesystem::path(outdir) / "report.html").string();
  files::requireDistinct({{"study file", opt.study_path}},
                         {{"results file", results}, {"report", html}});
  const std::string build_id = buildIdentity();
  const RunCache cache(cache_dir, build_id, readableOutput);
  if (mpi.rank() > 0) {
    workerLoop(mpi, planRecords(plan, cache),
               [&opt](const RunRecord& r) { return childArguments(r, opt.checkpoint_every); });
    return 0;
  }
  // From here on an interrupt stops the runs and exits 130 (the workers above stop with rank 0).
  installInterruptFlag();
  const auto t0 = std::chrono::steady_clock::now();
  RemoteWorkers remote(mpi);
  SchedulerOptions scheduling{jobs, opt.quiet, opt.checkpoint_every, {}};
  scheduling.earlier_cost = [](const RunRecord& r) {
    return r.request.kind == RunKind::Particles ? checkpointedCost(r.runPath())
                                                : std::pair<double, double>{0.0, 0.0};
  };
  RunSet runs(runAll(plan, cache, scheduling, mpi.size() > 1 ? &remote : nullptr));
  requireFinished(runs, cache_dir);
  // Follow-up rounds (more seeds for an undecided verdict) run on this rank: the worker ranks
  // have left their loop with the first round. Finished runs come from the cache.
  int round = 1;
  for (FollowUp more = study.followUp(runs); !more.runs.empty(); more = study.followUp(runs)) {
    if (!opt.quiet)
      fmt::print(stderr, "granwave study: {}\n", followUpLine(++round, more, runs, jobs));
    plan.insert(plan.end(), more.runs.begin(), more.runs.end());
    runs = RunSet(runAll(plan, cache, scheduling, nullptr));
    requireFinished(runs, cache_dir);
  }
  writeResults(results, study, file, runs, build_id, program_version);
  if (!opt.no_report)
    renderReport(results, html, (std::filesystem::path(outdir) / "report.log").string());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fmt::print("study           {} ({})\n", opt.study_path, file.kind());
  fmt::print("results         {}\n", results);
  if (!opt.no_report) fmt::print("report          {}\n", html);
  std::set<std::string> distinct;
  for (const RunRecord& r : runs.all()) distinct.insert(r.stem);
  fmt::print("wall time       {:.1f} s ({} runs, {} jobs{})\n", wall, distinct.size(), jobs,
             mpi.size() > 1 ? fmt::format(" + {} worker ranks", mpi.size() - 1) : "");
  return 0;
}

}  // namespace granwave
