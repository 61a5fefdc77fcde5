#include "hydro/ConstitutiveModel.hpp"

#include <cmath>
#include <numbers>

#include "hydro/SoundSpeed.hpp"

namespace granwave::hydro {

LocalState ConstitutiveModel::evaluate(double rho, double theta) const {
  const DiskGas gas{mass, sigma};
  const RestitutionAverages av = restitution.averages(theta);
  const TransportCoefficients t = transport == TransportSet::GarzoDufty
                                      ? garzoDuftyTransport(gas, rho, theta, av)
                                      : jenkinsRichmanTransport(gas, rho, theta, av);
  double limiter = 1.0;
  if (knudsen_length > 0)
    limiter = 1.0 / (1.0 + meanFreePath(gas, gas.numberDensity(rho)) / knudsen_length);
  LocalState s;
  s.p = t.p;
  s.viscosity = (t.lambda_b + t.eta) * limiter;  // d = 2: lambda_b + 2 eta (d - 1)/d
  s.kappa_theta = t.kappa_theta * limiter;
  s.cooling = t.D_c;
  s.sound_speed = adiabaticSoundSpeed(gas.areaFraction(gas.numberDensity(rho)), theta, restitution);
  return s;
}

double ConstitutiveModel::pressure(double rho, double theta) const {
  const DiskGas gas{mass, sigma};
  return rho * theta * pressureFactor(gas.areaFraction(gas.numberDensity(rho)), theta, restitution);
}

double ConstitutiveModel::sideWallSink(double p, double theta) const {
  return side_wall_width > 0 ? 2.0 / side_wall_width * wallDissipation(p, theta) : 0.0;
}

double ConstitutiveModel::wallDissipation(double p, double theta) const {
  // (1 - e_w^2) p sqrt(T / (2 pi m)) with the wall-averaged Phi_W (physics-hydro.md 2.2, 4.2)
  return wall_restitution.phiWall(theta) * p * std::sqrt(theta / (2 * std::numbers::pi));
}

}  // namespace granwave::hydro
