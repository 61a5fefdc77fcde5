#include "hydro/ConstitutiveModel.hpp"

namespace granwave::hydro {

double ConstitutiveModel::sideWallSink(double p, double theta) const {
  return side_wall_width > 0 ? 2.0 / side_wall_width * wallDissipation(p, theta) : 0.0;
}

double ConstitutiveModel::wallDissipation(double p, double theta) const {
  return wall_restitution.phiWall(theta) * p * std::sqrt(theta / (2 * std::numbers::pi));
}

}  // namespace granwave::hydro
