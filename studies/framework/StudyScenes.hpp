#pragma once
// Scenes of a study: a base scene file plus `section.key=value` overrides (the same syntax and
// checks as --set), and the hydro closure that matches a scene's restitution law.
#include <string>
#include <vector>

#include "hydro/RestitutionClosure.hpp"
#include "scene/Scene.hpp"
#include "studies/framework/StudyFile.hpp"

namespace granwave {

// Throws StudyError naming the study file, the scene and the override on any scene error.
// Particle runs keep one trajectory frame per cycle (the observables and live fields see
// every record), so a study's run files stay small.
Scene studyScene(const StudyFile& study, const std::string& scene_path,
                 const std::vector<std::string>& overrides);

// The Maxwell-averaged closure of the scene's law (hydro.restitution_model = "velocity"),
// or its constant e.
hydro::RestitutionClosure restitutionClosure(const Scene& scene);

// e_eff = sqrt(1 - <1 - e^2>) of the scene's law for a Maxwellian at the drive's temperature
// scale theta0 = v0^2 / 2 (T0 = m v0^2 / 2): the constant restitution that stands in for the
// velocity-dependent law in the constant-e models.
double effectiveRestitutionAtT0(const Scene& scene);

}  // namespace granwave
