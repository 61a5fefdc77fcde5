#include "hydro/TransportCoefficients.hpp"

#include <cmath>
#include <numbers>

#include "hydro/PairCorrelation.hpp"

namespace granwave::hydro {

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

double DiskGas::areaFraction(double n) const { return n * kPi * sigma * sigma / 4.0; }

double referenceViscosity(const DiskGas& gas, double theta) {
  return gas.mass / (2.0 * gas.sigma) * std::sqrt(theta / kPi);
}

double collisionFrequency(const DiskGas& gas, double n, double theta) {
  return 2.0 * gas.sigma * n * pairCorrelation(gas.areaFraction(n)) * std::sqrt(kPi * theta);
}

double meanFreePath(const DiskGas& gas, double n) {
  return 1.0 / (2.0 * std::numbers::sqrt2 * gas.sigma * n * pairCorrelation(gas.areaFraction(n)));
}

double CoolingRate::operator()(double n, double T) const {
  const double theta = T / gas.mass;
  return std::sqrt(kPi) * restitution.phiW(theta) * pairCorrelation(gas.areaFraction(n)) * n *
         gas.sigma * std::sqrt(theta);
}

TransportCoefficients jenkinsRichmanTransport(const DiskGas& gas, double rho, double theta,
                                              const RestitutionAverages& a) {
  const double nu = gas.areaFraction(gas.numberDensity(rho));
  const double g2 = pairCorrelation(nu);
  const double G = nu * g2;
  const double eta0 = referenceViscosity(gas, theta);
  TransportCoefficients t;
  t.p = rho * theta * (1.0 + a.phi_p * G);
  t.eta = eta0 * (1.0 / g2 + 2.0 * nu + (1.0 + 8.0 / kPi) * nu * G);
  t.lambda_b = eta0 * (8.0 / kPi) * a.phi_p * nu * G;
  t.kappa_theta = 4.0 * eta0 * (1.0 / g2 + 3.0 * nu + (9.0 / 4.0 + 4.0 / kPi) * nu * G);
  t.D_c = 4.0 / std::sqrt(kPi) * a.phi_w * rho * G * theta * std::sqrt(theta) / gas.sigma;
  return t;
}

GarzoDuftyReduced garzoDuftyReduced(double nu, const RestitutionAverages& a) {
  const double chi = pairCorrelation(nu);
  const double G = nu * chi;
  const double e = a.effectiveRestitution();  // kinetic factors
  const double phi_p = a.phi_p;               // collisional transfer, (1 + e)
  GarzoDuftyReduced r;
  r.p = 1.0 + phi_p * G;
  r.zeta = 0.5 * a.phi_w * chi;
  const double nu_eta = chi * (7.0 - 3.0 * e) * (1.0 + e) / 8.0;
  r.eta_k = (1.0 - 0.25 * (1.0 + e) * (1.0 - 3.0 * e) * G) / (nu_eta - 0.5 * r.zeta);
  r.lambda_b = 8.0 / kPi * phi_p * nu * G;
  r.eta = r.eta_k * (1.0 + 0.5 * phi_p * G) + 0.5 * r.lambda_b;
  const double nu_kappa = chi * 0.5 * (1.0 + e) * (0.5 + 15.0 / 8.0 * (1.0 - e));
  r.kappa_k = 0.5 * (1.0 + 3.0 / 8.0 * (1.0 + e) * (1.0 + e) * (2.0 * e - 1.0) * G) /
              (nu_kappa - 2.0 * r.zeta);
  r.kappa = r.kappa_k * (1.0 + 0.75 * phi_p * G) + 2.0 / kPi * phi_p * nu * G;
  return r;
}

TransportCoefficients garzoDuftyTransport(const DiskGas& gas, double rho, double theta,
                                          const RestitutionAverages& a) {
  const double n = gas.numberDensity(rho);
  const GarzoDuftyReduced r = garzoDuftyReduced(gas.areaFraction(n), a);
  const double eta0 = referenceViscosity(gas, theta);
  const double nT = rho * theta;
  const double nu0 = 2.0 * std::sqrt(kPi) * n * gas.sigma * std::sqrt(theta);  // n T / eta0
  TransportCoefficients t;
  t.p = r.p * nT;
  t.eta = r.eta * eta0;
  t.lambda_b = r.lambda_b * eta0;
  t.kappa_theta = 4.0 * eta0 * r.kappa;  // m kappa* kappa0, kappa0 = 4 eta0 / m
  t.D_c = r.zeta * nu0 * nT;
  return t;
}

}  // namespace granwave::hydro
