#pragma once
// The sound-speed study (docs/studies.md): does constant-restitution sound-speed and shock
// theory hold for the fronts the particles show? Each impact front of dry and wet runs over
// N and Gamma is compared with the adiabatic and isothermal sound speeds of the gas ahead,
// the Rankine-Hugoniot and strong-shock speeds, the compaction-front limit, and mass
// conservation across the measured states.
#include <memory>

#include "studies/framework/Study.hpp"

namespace granwave {

std::unique_ptr<Study> makeSoundSpeedStudy(StudyFile& file);

}  // namespace granwave
