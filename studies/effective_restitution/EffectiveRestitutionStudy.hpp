#pragma once
// The effective-restitution study (docs/studies.md): one constant e_eff fitted to particle
// data three ways (free cooling, collision statistics of the driven run, constant-e hydro
// fitted to the particle fields), against the Maxwell-averaged theory e_eff(T).
#include <memory>

#include "studies/framework/Study.hpp"

namespace granwave {

std::unique_ptr<Study> makeEffectiveRestitutionStudy(StudyFile& file);

}  // namespace granwave
