#pragma once
// Shared by the hydro tests: the paper's glass beads and a constitutive model built from a
// pair and a wall restitution law (Knudsen limiter at one diameter, as `granwave hydro`).
#include <numbers>

#include "hydro/ConstitutiveModel.hpp"

namespace granwave::hydro::test {

inline constexpr double kD = 0.002;  // m, particle diameter
inline const double kMass = 2580 * std::numbers::pi * kD * kD * kD / 6;
inline const double kDisk = std::numbers::pi * kD * kD / 4;  // disk area, m^2

inline ConstitutiveModel beadModel(RestitutionClosure pairs, RestitutionClosure walls) {
  ConstitutiveModel m;
  m.mass = kMass;
  m.sigma = kD;
  m.restitution = pairs;
  m.wall_restitution = walls;
  m.knudsen_length = kD;
  return m;
}

}  // namespace granwave::hydro::test
