#pragma once
// The continuum model of a scene (docs/hydro.md): the closures of its contact law, the
// container and drive the PDE sees, and the run's sampling, length and tolerances, as
// `granwave hydro` integrates it and the studies compare with it. The particles' counterpart is
// particles/EngineConfigFromScene.
#include "hydro/ConstitutiveModel.hpp"
#include "hydro/HydroSimulation.hpp"
#include "hydro/RestitutionClosure.hpp"
#include "scene/Scene.hpp"
#include "scene/SceneDerived.hpp"

namespace granwave {

// The Maxwell-averaged closure of the scene's law (hydro.restitution_model = "velocity"),
// or its constant e.
hydro::RestitutionClosure restitutionClosure(const Scene& scene);

// e_eff = sqrt(1 - <1 - e^2>) of the scene's law for a Maxwellian at the drive's temperature
// scale theta0 = v0^2 / 2 (T0 = m v0^2 / 2): the constant restitution that stands in for the
// velocity-dependent law in the constant-e models.
double effectiveRestitutionAtT0(const Scene& scene);

// The paper's continuum: the scene's closures, with the same restitution law at the walls.
hydro::ConstitutiveModel constitutiveModel(const Scene& scene, const SceneDerived& derived);
// Cells, container height, gravity, drive; the drive ramps up over two cycles from the settled
// layer.
hydro::HydroGeometry hydroGeometry(const Scene& scene, const SceneDerived& derived);
// The numerical parameters of the discrete operator (docs/hydro.md, "Sensitivity").
hydro::HydroRegularisation hydroRegularisation(const Scene& scene);
// M phases per cycle, at most run.duration x f cycles (at least 8), the scene's tolerances, the
// start (hydro.start) and its temperature (hydro.initial_temperature, in T0).
hydro::HydroRunOptions hydroRunOptions(const Scene& scene, const SceneDerived& derived);

}  // namespace granwave
