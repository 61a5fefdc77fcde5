#include "hydro/SoundSpeed.hpp"

#include <cmath>

#include "hydro/PairCorrelation.hpp"

namespace granwave::hydro {

namespace {

constexpr double kDimension = 2.0;  // translational kinetics of disks

// F + nu dF/dnu at fixed theta (the isothermal bracket).
double isothermalBracket(double nu, double phi_p) {
  const double g2 = pairCorrelation(nu);
  return 1.0 + phi_p * nu * g2 + nu * phi_p * (g2 + nu * pairCorrelationDerivative(nu));
}

}  // namespace

double pressureFactor(double nu, double theta, const RestitutionClosure& restitution) {
  return 1.0 + restitution.phiP(theta) * nu * pairCorrelation(nu);
}

double adiabaticSoundSpeed(double nu, double theta, const RestitutionClosure& restitution) {
  if (theta <= 0.0) return 0.0;
  const double phi_p = restitution.phiP(theta);
  const double G = nu * pairCorrelation(nu);
  const double F = 1.0 + phi_p * G;
  const double theta_dF_dtheta = theta * restitution.dPhiPdTheta(theta) * G;
  const double c2 =
      theta * (isothermalBracket(nu, phi_p) + (2.0 / kDimension) * F * (F + theta_dF_dtheta));
  return std::sqrt(c2);
}

double isothermalSoundSpeed(double nu, double theta, const RestitutionClosure& restitution) {
  if (theta <= 0.0) return 0.0;
  return std::sqrt(theta * isothermalBracket(nu, restitution.phiP(theta)));
}

}  // namespace granwave::hydro
