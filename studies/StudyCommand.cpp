#include "studies/StudyCommand.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "h5/AtomicFile.hpp"
#include "studies/ChildProcess.hpp"
#include "studies/InterruptFlag.hpp"
#include "studies/RemoteWorkers.hpp"
#include "studies/ReportWriter.hpp"
#include "studies/RunCache.hpp"
#include "studies/RunOutputs.hpp"
#include "studies/RunScheduler.hpp"
#include "studies/Study.hpp"
#include "studies/Version.hpp"

namespace granwave {

namespace {

// The cost of every run: the report's last section and /runs in results.h5.
void writeRunCosts(const RunSet& runs, h5::File& f, Report& report) {
  Table t;
  t.title = "Runs and their cost";
  t.caption =
      "Every run of the study, as measured when it was made (reused runs keep their original "
      "cost). Work: ED events, or CVODE steps / right-hand-side evaluations.";
  t.columns = {"run", "method", "status", "wall s", "CPU s", "work"};
  std::vector<std::string> labels, kinds, status;
  std::vector<double> wall, cpu, work;
  for (const RunRecord& r : runs.all()) {
    const bool hydro = r.request.kind == RunKind::Hydro;
    const bool lammps = r.request.kind == RunKind::Lammps;
    const std::string method = hydro ? "hydro" : lammps ? "LAMMPS (DEM)" : "particles";
    std::string w = "-";
    double work_value = 0;
    if (r.ok) {
      if (lammps) {
        const LammpsTrajectory l = readLammpsTrajectory(r.lammpsPath());
        work_value = static_cast<double>(l.last_step);
        w = fmt::format("{:.3g} time steps", work_value);
      } else if (hydro) {
        const HydroFields h = readHydroFields(r.hydroPath());
        work_value = static_cast<double>(h.steps);
        w = fmt::format("{} steps / {} RHS", h.steps, h.rhs_evals);
      } else {
        const RunObservables o = readRunObservables(r.runPath());
        work_value = static_cast<double>(o.events);
        w = fmt::format("{:.3g} events", static_cast<double>(o.events));
      }
    }
    t.rows.push_back({r.request.label, method,
                      r.ok ? (r.reused ? "ok (reused)" : "ok") : "failed: " + r.message,
                      fmt::format("{:.2f}", r.wall), fmt::format("{:.2f}", r.cpu), w});
    labels.push_back(r.request.label);
    kinds.push_back(method);
    status.push_back(r.ok ? "ok" : r.message);
    wall.push_back(r.wall);
    cpu.push_back(r.cpu);
    work.push_back(work_value);
  }
  f.createGroup("/runs");
  f.writeStringArrayAttribute("/runs", "label", labels);
  f.writeStringArrayAttribute("/runs", "method", kinds);
  f.writeStringArrayAttribute("/runs", "status", status);
  f.writeDataset("/runs/wall_seconds", wall, {wall.size()});
  f.writeDataset("/runs/cpu_seconds", cpu, {cpu.size()});
  f.writeDataset("/runs/work", work, {work.size()});
  ReportSection& s = report.section("Runs and cost");
  s.add(std::move(t));
}

std::string reportScript() {
  if (const char* env = std::getenv("GRANWAVE_REPORT_SCRIPT")) return env;
  return GRANWAVE_REPORT_SCRIPT;
}

void renderReport(const std::string& results, const std::string& html, const std::string& log) {
  const char* env = std::getenv("GRANWAVE_PYTHON");
  const std::string python = env ? env : "/usr/bin/python3";
  if (!std::filesystem::exists(python))
    throw std::runtime_error(
        fmt::format("{} not found: the report needs Debian's python3-matplotlib and python3-h5py "
                    "(results are in {}; use --no-report to skip the page)",
                    python, results));
  std::filesystem::remove(log);
  ChildProcess child(python, {reportScript(), results, html}, log);
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

}  // namespace

void addStudyCommand(CLI::App& app, StudyOptions& opt) {
  CLI::App* cmd = app.add_subcommand(
      "study", "Run a study (particles, fields, hydro, analysis) and write its report");
  cmd->add_option("study", opt.study_path, "Study file (TOML; docs/studies.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", opt.output,
                  "Output directory (results.h5, report.html, runs/); default: the study "
                  "file's stem");
  cmd->add_option("--cache", opt.cache,
                  "Run cache directory, shared by studies that use the same runs (default: "
                  "OUTDIR/runs)");
  cmd->add_option("-j,--jobs", opt.jobs, "Runs at a time (default: [study] jobs, else all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--checkpoint-every", opt.checkpoint_every,
                  "Seconds of wall time between checkpoints of a particle run, from which a "
                  "killed study continues it (0 = none)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", opt.quiet, "No progress lines");
  cmd->add_flag("--no-report", opt.no_report, "Write results.h5 only, no report.html");
}

int runStudy(const StudyOptions& opt, const MpiSession& mpi) {
  StudyFile file = StudyFile::load(opt.study_path);
  const std::unique_ptr<Study> study = makeStudy(file);
  int jobs = file.integer("study", "jobs", 0);
  file.rejectUnknownKeys();
  if (opt.jobs > 0) jobs = opt.jobs;
  // Under mpirun each rank is meant to have a core of its own: one run at a time per rank.
  if (jobs <= 0 && mpi.size() > 1) jobs = 1;
  if (jobs <= 0) jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const std::vector<RunRequest> plan = study->plan();

  std::string outdir = opt.output;
  if (outdir.empty()) outdir = std::filesystem::path(opt.study_path).stem().string();
  std::filesystem::create_directories(outdir);
  const std::string cache_dir =
      opt.cache.empty() ? (std::filesystem::path(outdir) / "runs").string() : opt.cache;
  const std::string build_id = buildIdentity();
  const RunCache cache(cache_dir, build_id);
  if (mpi.rank() > 0) {
    workerLoop(mpi, planRecords(plan, cache),
               [&opt](const RunRecord& r) { return childArguments(r, opt.checkpoint_every); });
    return 0;
  }
  const auto t0 = std::chrono::steady_clock::now();
  RemoteWorkers remote(mpi);
  const RunSet runs(runAll(plan, cache, {jobs, opt.quiet, opt.checkpoint_every},
                           mpi.size() > 1 ? &remote : nullptr));
  // A run that did not finish (killed, could not start) is not a result: no results.h5.
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

  const std::string results = (std::filesystem::path(outdir) / "results.h5").string();
  const std::string html = (std::filesystem::path(outdir) / "report.html").string();
  {
    h5::AtomicFile af(results);
    h5::File& f = af.file();
    Report report;
    report.title = study->title();
    f.createGroup("/results");
    study->analyse(runs, f, report);
    writeRunCosts(runs, f, report);
    f.writeStringAttribute("/", "format", "granwave-study-1");
    f.writeStringAttribute("/", "study", file.kind());
    f.writeStringAttribute("/", "title", report.title);
    f.writeStringAttribute("/", "summary", report.summary);
    f.writeStringAttribute("/", "granwave_version", kVersion);
    f.writeStringAttribute("/", "build_id", build_id);
    f.writeStringDataset("/study_file", file.text());
    writeReport(f, report);
    // An interrupt during the analysis: nothing is committed; the runs stay cached.
    if (installInterruptFlag().load())
      throw StudyInterrupted("interrupted during the analysis; run the same command again");
    af.commit();
  }
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
