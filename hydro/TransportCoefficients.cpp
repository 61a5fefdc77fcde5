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

namespace {
TransportCoefficients fromKernel(const Transport<double>& k) {
  return {k.p, k.eta, k.lambda_b, k.kappa_theta, k.D_c};
}
}  // namespace

TransportCoefficients jenkinsRichmanTransport(const DiskGas& gas, double rho, double theta,
                                              const RestitutionAverages& a) {
  const double g2 = pairCorrelation(gas.areaFraction(gas.numberDensity(rho)));
  return fromKernel(jenkinsRichman(gas, rho, theta, g2, a.phi_w, a.phi_p));
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
  const double g2 = pairCorrelation(gas.areaFraction(gas.numberDensity(rho)));
  return fromKernel(garzoDufty(gas, rho, theta, g2, a.phi_w, a.phi_p));
}

}  // namespace granwave::hydro
