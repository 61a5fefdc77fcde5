#pragma once
// The runs the methods comparison adds to the wave-fronts study's plan, in the order the study
// plans them: the failure map (particles without the TC model, hydro over Gamma x grid x
// tolerance), the model hierarchy's hydro candidates beyond the paper's two closures
// (Garzo-Dufty, rough particles), cost against accuracy (particles over the cycles averaged,
// hydro over grid x tolerance), and LAMMPS on the paper's dry scene.
#include <optional>
#include <string>
#include <vector>

#include "studies/contract/StudyFile.hpp"
#include "studies/method_comparison/MethodComparisonConfig.hpp"
#include "studies/runner/RunRequest.hpp"

namespace granwave {

// One run of `law` with the study's overrides and `overrides`; particle runs last `duration`.
struct PlannedRun {
  RunKind kind = RunKind::Particles;
  int law = 0;
  std::string label;
  std::vector<std::string> overrides;
  double duration = 0;       // s (particle runs)
  std::string failure_note;  // a failure of this run is a result (RunRequest.hpp)
};

std::vector<PlannedRun> failureMapRuns(const MethodComparisonConfig& config, int law);
std::vector<PlannedRun> modelHydroRuns(const MethodComparisonConfig& config, int law);
std::vector<PlannedRun> costRuns(const MethodComparisonConfig& config);

// The LAMMPS run of the paper's dry scene (studies/lammps/paper-scene.lmp; its contact model
// has a constant e_n = 0.9, so it stands beside the dry particles), if [lammps] run asks for it
// and the program is there; sets config.lammps. Installs Debian's lammps if asked and missing;
// otherwise a missing executable that is required is a study-file error.
std::optional<RunRequest> lammpsRequest(StudyFile& file, MethodComparisonConfig& config);

}  // namespace granwave
