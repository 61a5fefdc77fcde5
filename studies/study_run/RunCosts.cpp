#include "studies/study_run/RunCosts.hpp"

#include <fmt/format.h>

#include "studies/contract/StudyResults.hpp"
#include "studies/run_files/Hydro2DRunFile.hpp"
#include "studies/run_files/HydroRunFile.hpp"
#include "studies/run_files/RunOutputs.hpp"

namespace granwave {

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
      } else if (hydro && r.request.scene.hydro.dimensions == 2) {
        const Hydro2DSolverRecord h = readHydro2DSolver(r.hydroPath());
        work_value = static_cast<double>(h.steps);
        w = fmt::format("{} steps / {} RHS", h.steps, h.rhs_evals);
      } else if (hydro) {
        const HydroRunContent h = readHydroRunFile(r.hydroPath());
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
  putSeries(f, "/runs/wall_seconds", wall, "s");
  putSeries(f, "/runs/cpu_seconds", cpu, "s");
  // Events (particles), CVODE steps (hydro) or time steps (LAMMPS): counts.
  putSeries(f, "/runs/work", work, "1");
  ReportSection& s = report.section("Runs and cost");
  s.add(std::move(t));
}

}  // namespace granwave
