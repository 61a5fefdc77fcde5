#pragma once
// One hydro run of a scene, as `granwave hydro` makes it: the scene's continuum
// (HydroModel.hpp) integrated from the settled layer to its periodic state, and what the hydro
// run file holds of it: the plate-frame fields, the lab frame with its fronts (LabFrame.hpp)
// and the solver's figures.
#include <atomic>
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

// Refuses a scene the continuum cannot integrate (no drive, no bottom and lid, rough particles
// that are smooth) with a one-line SceneError naming `scene_name`.
void requireHydroScene(const Scene& scene, const std::string& scene_name);

// Runs the scene (requireHydroScene first). A solver failure is a hydro::HydroFailure; an
// `interrupt` set (SIGINT/SIGTERM) ends it with hydro::HydroInterrupted at the next phase. A
// line on `progress` (nullptr: none) says how many cycles it may take.
HydroRunContent runHydroScene(const Scene& scene, const std::string& scene_name,
                              std::FILE* progress, const std::atomic<bool>* interrupt = nullptr);

}  // namespace granwave
