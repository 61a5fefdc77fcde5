#pragma once
// Navier-Stokes transport coefficients of smooth inelastic hard disks, d = 2
// (docs/hydro.md, "Closures"). Units (2D, per unit length of the layer's width):
//
//   p            pressure,                         N/m = kg/s^2
//   eta          shear viscosity,                  kg/s
//   lambda_b     bulk viscosity,                   kg/s
//   kappa_theta  heat conductivity for theta:      kg/s, heat flux q = -kappa_theta d(theta)/dz
//                in W/m. kappa_theta = m kappa_T, where kappa_T (1/s) is the conductivity for
//                T = m theta in q = -kappa grad T; kappa_theta = 4 eta0 kappa*.
//   D_c          collisional energy loss rate,      W/m^2 = kg/s^3
//
// with rho = m n, nu = n pi sigma^2/4, G = nu g2(nu) (Henderson), theta = T/m and the reference
// (dilute, elastic) values
//
//   eta0 = (1/(2 sigma)) sqrt(m T / pi),   kappa0 = 4 eta0 / m,   nu0 = n T / eta0
//        = 2 sqrt(pi) n sigma sqrt(theta).
//
// (A) Jenkins-Richman / elastic-Enskog compact set (1.5 A): the elastic 2D Enskog (Gass)
//     coefficients, with (1 + e) only in p and lambda_b and (1 - e^2) in D_c:
//
//     p        = rho theta [1 + Phi_P G]
//     eta      = (sqrt(pi)/8) rho sigma sqrt(theta) [1/G + 2 + (1 + 8/pi) G]
//              = eta0 [1/g2 + 2 nu + (1 + 8/pi) nu G]    (the form evaluated: finite at n = 0)
//     lambda_b = (Phi_P/sqrt(pi)) rho sigma sqrt(theta) G = eta0 (8/pi) Phi_P nu G
//     kappa_th = (sqrt(pi)/2) rho sigma sqrt(theta) [1/G + 3 + (9/4 + 4/pi) G]
//              = 4 eta0 [1/g2 + 3 nu + (9/4 + 4/pi) nu G]
//     D_c      = (4/sqrt(pi)) Phi_W rho G theta^{3/2} / sigma
//
// (B) Garzo-Dufty (1999) Enskog, inelastic, first Sonine, c* = 0, d = 2 (1.5 B), reduced
//     X* = X / X0 (phi = nu, chi = g2):
//
//     p*       = 1 + Phi_P phi chi
//     zeta*    = (1/2) Phi_W chi                               zeta = zeta* nu0
//     nu_eta*  = chi (7 - 3e)(1 + e)/8
//     eta_k*   = [1 - (1/4)(1 + e)(1 - 3e) phi chi] / (nu_eta* - zeta*/2)
//     lambda_b*= (8/pi) Phi_P phi^2 chi
//     eta*     = eta_k* [1 + (1/2) Phi_P phi chi] + (1/2) lambda_b*
//     nu_kap*  = chi ((1 + e)/2) [1/2 + (15/8)(1 - e)]
//     kappa_k* = (1/2) [1 + (3/8)(1 + e)^2 (2e - 1) phi chi] / (nu_kap* - 2 zeta*)
//     kappa*   = kappa_k* [1 + (3/4) Phi_P phi chi] + (2/pi) Phi_P phi^2 chi
//
//     eta = eta* eta0, lambda_b = lambda_b* eta0, kappa_theta = m kappa* kappa0 = 4 eta0 kappa*,
//     D_c = zeta n T (same as set A).
//
// Velocity-dependent restitution (4.6, local-Maxwellian closure): (1 - e^2) -> Phi_W(theta) in
// zeta and D_c; (1 + e) -> Phi_P(theta) in p and the collisional-transfer terms (the factors
// multiplying phi chi outside eta_k*, kappa_k*, and lambda_b*); the kinetic parts eta_k*,
// kappa_k* (nu_eta*, nu_kappa* and their numerators) at e = e_eff = sqrt(1 - Phi_W). With
// Phi_W = 1 - e^2, Phi_P = 1 + e this is exactly the constant-e set. At e = 1, (A) = (B).
//
// Building blocks (1.4): collision frequency omega = 2 sigma n g2 sqrt(pi theta), mean free
// path l = 1/(2 sqrt 2 sigma n g2), cooling rate zeta = sqrt(pi) Phi_W g2 n sigma sqrt(theta),
// Haff time 2/zeta.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "hydro/RestitutionClosure.hpp"
#include "hydro/Scalar.hpp"

namespace granwave::hydro {

// The particles: mass m (kg, of the sphere) and diameter sigma (m).
struct DiskGas {
  double mass = 0;
  double sigma = 0;
  double numberDensity(double rho) const { return rho / mass; }  // 1/m^2
  double areaFraction(double n) const;                           // n pi sigma^2 / 4
};

struct TransportCoefficients {
  double p = 0;            // N/m
  double eta = 0;          // kg/s
  double lambda_b = 0;     // kg/s
  double kappa_theta = 0;  // kg/s, q = -kappa_theta d(theta)/dz
  double D_c = 0;          // W/m^2
};

// The reduced Garzo-Dufty quantities (set B) at area fraction nu.
struct GarzoDuftyReduced {
  double p = 0, zeta = 0, eta_k = 0, eta = 0, lambda_b = 0, kappa_k = 0, kappa = 0;
};
GarzoDuftyReduced garzoDuftyReduced(double nu, const RestitutionAverages& averages);

// The same sets at a given pair correlation g2 (from any PairCorrelation form) and averaged
// restitution factors, on any scalar type (hydro/Scalar.hpp); the kernels the solver uses.
template <class S>
struct Transport {
  S p, eta, lambda_b, kappa_theta, D_c;
};

// Garzo-Dufty's kinetic parts are first-Sonine results for 0 < e <= 1 whose denominators
// nu_eta* - zeta*/2 and nu_kappa* - 2 zeta* vanish as e -> 0 (nu ~ 0.78 and above: the heat
// conductivity turns negative for the cold wet gas, e_eff -> 0). They are evaluated at
// e_k = max(e_eff, kGarzoDuftyRestitutionFloor) (smoothly), collisional transfer and cooling at
// the true averages: docs/hydro.md, "Closures inside their range".
inline constexpr double kGarzoDuftyRestitutionFloor = 0.5;

template <class S>
Transport<S> jenkinsRichman(const DiskGas& gas, const S& rho, const S& theta, const S& g2,
                            const S& phi_w, const S& phi_p) {
  using std::sqrt;
  constexpr double kPi = std::numbers::pi;
  const S nu = rho * (kPi * gas.sigma * gas.sigma / (4.0 * gas.mass));
  const S G = nu * g2;
  const S eta0 = gas.mass / (2.0 * gas.sigma) * sqrt(theta / kPi);
  Transport<S> t;
  t.p = rho * theta * (1.0 + phi_p * G);
  t.eta = eta0 * (1.0 / g2 + 2.0 * nu + (1.0 + 8.0 / kPi) * nu * G);
  t.lambda_b = eta0 * (8.0 / kPi) * phi_p * nu * G;
  t.kappa_theta = 4.0 * eta0 * (1.0 / g2 + 3.0 * nu + (9.0 / 4.0 + 4.0 / kPi) * nu * G);
  t.D_c = 4.0 / std::sqrt(kPi) * phi_w * rho * G * theta * sqrt(theta) / gas.sigma;
  return t;
}

template <class S>
Transport<S> garzoDufty(const DiskGas& gas, const S& rho, const S& theta, const S& g2,
                        const S& phi_w, const S& phi_p) {
  using std::sqrt;
  constexpr double kPi = std::numbers::pi;
  const double f2 = kGarzoDuftyRestitutionFloor * kGarzoDuftyRestitutionFloor;
  const S n = rho / gas.mass;
  const S nu = n * (kPi * gas.sigma * gas.sigma / 4.0);
  const S G = nu * g2;
  // e_k^2 = max(1 - Phi_W, floor^2), blended over +-0.05: positive, so sqrt is differentiable,
  // and exactly 1 - Phi_W for e_eff >= 0.55.
  const S e = sqrt(blendedMax(S(1.0 - phi_w), f2, 0.05));
  const S zeta_k = 0.5 * (1.0 - e * e) * g2;  // zeta* at e_k, inside the kinetic parts
  const S nu_eta = g2 * (7.0 - 3.0 * e) * (1.0 + e) / 8.0;
  const S eta_k = (1.0 - 0.25 * (1.0 + e) * (1.0 - 3.0 * e) * G) / (nu_eta - 0.5 * zeta_k);
  const S lambda_b = 8.0 / kPi * phi_p * nu * G;
  const S eta = eta_k * (1.0 + 0.5 * phi_p * G) + 0.5 * lambda_b;
  const S nu_kappa = g2 * 0.5 * (1.0 + e) * (0.5 + 15.0 / 8.0 * (1.0 - e));
  const S kappa_k = 0.5 * (1.0 + 3.0 / 8.0 * (1.0 + e) * (1.0 + e) * (2.0 * e - 1.0) * G) /
                    (nu_kappa - 2.0 * zeta_k);
  const S kappa = kappa_k * (1.0 + 0.75 * phi_p * G) + 2.0 / kPi * phi_p * nu * G;
  const S eta0 = gas.mass / (2.0 * gas.sigma) * sqrt(theta / kPi);
  const S nu0 = 2.0 * std::sqrt(kPi) * n * gas.sigma * sqrt(theta);
  Transport<S> t;
  t.p = (1.0 + phi_p * G) * rho * theta;
  t.eta = eta * eta0;
  t.lambda_b = lambda_b * eta0;
  t.kappa_theta = 4.0 * eta0 * kappa;
  t.D_c = 0.5 * phi_w * g2 * nu0 * rho * theta;
  return t;
}

// rho > 0 (kg/m^2), theta >= 0 (m^2/s^2); averages = closure.averages(theta). Henderson g2.
TransportCoefficients jenkinsRichmanTransport(const DiskGas& gas, double rho, double theta,
                                              const RestitutionAverages& averages);
TransportCoefficients garzoDuftyTransport(const DiskGas& gas, double rho, double theta,
                                          const RestitutionAverages& averages);

// eta0 = (m/(2 sigma)) sqrt(theta/pi), kg/s.
double referenceViscosity(const DiskGas& gas, double theta);
// omega = 2 sigma n g2 sqrt(pi theta), collisions per particle per second.
double collisionFrequency(const DiskGas& gas, double n, double theta);
// l = 1 / (2 sqrt 2 sigma n g2), m.
double meanFreePath(const DiskGas& gas, double n);

// zeta(n, T) = sqrt(pi) Phi_W(T/m) g2(nu) n sigma sqrt(T/m), 1/s; T in J (= k T). D_c = zeta n T.
struct CoolingRate {
  DiskGas gas;
  RestitutionClosure restitution;
  double operator()(double n, double T) const;
  // Haff time tau_H = 2 / zeta: T(t) = T0 / (1 + t/tau_H)^2 for constant e.
  double haffTime(double n, double T) const { return 2.0 / (*this)(n, T); }
};

}  // namespace granwave::hydro
