#pragma once
// One hydro run of a scene, as `granwave hydro` makes it: the scene's continuum
// (HydroModel.hpp) integrated from the settled layer to its periodic state, and what the hydro
// run file holds of it: the plate-frame fields, the lab frame with its fronts (LabFrame.hpp)
// and the solver's figures.
#include <cstdio>
#include <string>

#include "hydro/HydroSimulation.hpp"
#include "scene/Scene.hpp"
#include "scene/SceneDerived.hpp"
#include "studies/run_files/HydroRunFile.hpp"

namespace granwave {

// What goes into HYDRO.h5 from a finished run.
HydroRunContent hydroRunContent(const Scene& scene, const SceneDerived& derived,
                                const hydro::HydroResult& result,
                                const hydro::HydroRunOptions& options);

// A scene without drive or without bottom and lid is refused with a one-line
// std::runtime_error naming `scene_name`.
void requireHydroScene(const Scene& scene, const std::string& scene_name);

// Runs the scene. A scene without drive or without bottom and lid is refused with a one-line
// std::runtime_error naming `scene_name`; a solver failure is a hydro::HydroFailure. A line on
// `progress` (nullptr: none) says how many cycles it may take.
HydroRunContent runHydroScene(const Scene& scene, const std::string& scene_name,
                              std::FILE* progress);

}  // namespace granwave
