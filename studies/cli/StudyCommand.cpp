#include "studies/cli/StudyCommand.hpp"

#include <CLI/CLI.hpp>

#include "studies/cli/OptionChecks.hpp"
#include "studies/cli/StudyKinds.hpp"
#include "studies/cli/Version.hpp"

namespace granwave {

void addStudyCommand(CLI::App& app, StudyOptions& opt) {
  CLI::App* cmd = app.add_subcommand(
      "study", "Run a study (particles, fields, hydro, analysis) and write its report");
  cmd->add_option("study", opt.study_path, "Study file (TOML; docs/studies.md)")
      ->required()
      ->check(regularInputFile());
  cmd->add_option("-o,--output", opt.output,
                  "Output directory (results.h5, report.html, runs/); default: the study "
                  "file's stem");
  cmd->add_option("--cache", opt.cache,
                  "Run cache directory, shared by studies that use the same runs (default: "
                  "OUTDIR/runs)");
  cmd->add_option("-j,--jobs", opt.jobs, "Runs at a time (default: [study] jobs, else all cores)")
      ->check(numberAbove(0, true));
  cmd->add_option("--checkpoint-every", opt.checkpoint_every,
                  "Seconds of wall time between checkpoints of a particle run, from which a "
                  "killed study continues it (0 = none)")
      ->check(numberAbove(0, true))
      ->check(finiteNumber())
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", opt.quiet, "No progress lines");
  cmd->add_flag("--no-report", opt.no_report, "Write results.h5 only, no report.html");
  cmd->add_flag("--plan", opt.plan,
                "List the runs the study makes (method, cached or to do, label) and stop: "
                "nothing is run or written");
}

int runStudy(const StudyOptions& opt, const MpiSession& mpi) {
  StudyFile file = StudyFile::load(opt.study_path);
  const std::unique_ptr<Study> study = makeStudy(file);
  const int file_jobs = file.integer("study", "jobs", 0);
  if (file_jobs < 0) file.fail("study", "jobs", "expected 0 (one per core) or more runs at a time");
  file.rejectUnknownKeys();
  if (opt.plan) return mpi.rank() == 0 ? printStudyPlan(opt, *study) : 0;
  return runStudyPlan(opt, file, *study, file_jobs, mpi, kVersion);
}

}  // namespace granwave
