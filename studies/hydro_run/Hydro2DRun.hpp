#pragma once
// One 2D hydro run of a scene (hydro.dimensions = 2), as `granwave hydro` makes it: the scene's
// continuum (HydroModel.hpp: the same closures, geometry, tolerances and start as the 1D run)
// on hydro.columns columns across the container's width, periodic or between side walls as
// container.periodic_x says, the column masses perturbed by hydro.perturbation (seeded by
// run.seed), integrated for the 1D run's cycles (hydro/HydroSimulation2D.hpp), and what the 2D
// run file holds of it (studies/run_files/Hydro2DRunFile.hpp).
#include <cstdio>
#include <memory>
#include <string>

#include "hydro/HydroSimulation2D.hpp"
#include "scene/Scene.hpp"
#include "scene/SceneDerived.hpp"
#include "studies/run_files/Hydro2DRunFile.hpp"

namespace granwave {

// hydro.columns, or one per 4 d of the width when 0.
int hydroColumns(const Scene& scene);

// The scene's 2D operator: its closures (side walls explicit, so no 1D side-wall sink), the
// columns, the seeded column masses.
std::unique_ptr<hydro::GranularHydro2D> hydro2DOperator(const Scene& scene,
                                                        const SceneDerived& derived);

// The run's options: the 1D run's sampling, cycle budget, tolerances and start, the window
// the last two cycles.
hydro::Hydro2DRunOptions hydro2DRunOptions(const Scene& scene, const SceneDerived& derived);

// What goes into the 2D run file from a finished run.
Hydro2DRunContent hydro2DRunContent(const Scene& scene, const hydro::GranularHydro2D& op,
                                    const hydro::Hydro2DResult& result,
                                    const hydro::Hydro2DRunOptions& options);

// Runs the scene; refused as runHydroScene refuses (HydroRun.hpp); a solver failure is a
// hydro::HydroFailure.
Hydro2DRunContent runHydro2DScene(const Scene& scene, const std::string& scene_name,
                                  std::FILE* progress);

}  // namespace granwave
