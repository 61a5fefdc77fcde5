#pragma once
// Collisional exchange between translation and rotation for rough (frictional) particles: the
// two-temperature kinetic theory of homogeneous cooling (Huthmann & Zippelius, PRE 56, R6275
// (1997); Luding, Huthmann, McNamara & Zippelius, PRE 58, 3416 (1998)), written for the
// paper's spheres moving in a plane: two translational degrees of freedom (temperature theta
// = T/m per degree), one rotational (theta_r = I <omega^2>/m), q = 4 I/(m sigma^2) = 2/5.
// Per unit mass, in a gas of area fraction nu with pair correlation g2 (docs/hydro.md,
// "Rough particles"):
//
//   d theta/dt   = G' [ -A theta^(3/2) + B theta^(1/2) theta_r ]
//   d theta_r/dt = 2 G' [ B theta^(3/2) - C theta^(1/2) theta_r ]
//   G' = 16 nu g2 / (sqrt(pi) sigma)
//   A = <1 - e_n^2>/4 + (eta1 - eta2^2)/2,  B = eta2^2/(2q),  C = (eta1 - eta2^2/q)/(2q)
//
// The factor 2 in the rotational rate is d_t/d_r. With a constant tangential restitution
// beta, eta1 = eta, eta2^2 = eta^2, eta = q(1 + beta)/(2(1 + q)), and the elastic, perfectly
// rough limit (e_n = beta = 1) has A = B = C = q/(2(1+q)^2): theta + theta_r/2 conserved.
// The paper's tangential law is Walton's: sticking with beta = e_t0 unless the impulse
// exceeds Coulomb's mu times the normal one. Averaged over a Maxwellian of the relative
// contact velocity at the temperature ratio R = theta_r/theta (the tangential contact speed's
// variance grows with R), with eta0 = q(1 + e_t0)/(2(1 + q)), kappa = mu (1 + e_n)/(2 eta0),
// phi = q/(q + R), lambda = kappa sqrt(phi), c0 = lambda/sqrt(1 + lambda^2):
//   eta1 = eta0 c0,  eta2^2 = 2 eta0^2 c0^2/(1 + c0)
// (mu -> infinity: c0 -> 1, constant eta0). The normal part <1 - e_n^2> is the Maxwell-
// averaged Phi_W already in the cooling D_c; (1 + e_n) in kappa is its momentum average Phi_P.
// The constant-beta coefficients and this average were checked against a Monte Carlo of the
// collision rule over Maxwellian pairs (0.2-0.5 %); tests/hydro check the homogeneous cooling
// state's ratio R* against the closed form B R^2 + (2C - A) R - 2B = 0.
#include <cmath>
#include <numbers>

#include "hydro/Scalar.hpp"

namespace granwave::hydro {

struct RoughParticles {
  bool enabled = false;
  double friction = 0.5;              // Coulomb mu
  double tangential_sticking = 0.35;  // e_t0, the sticking tangential restitution
  double inertia = 0.4;               // q = 4 I/(m sigma^2): 2/5 for a sphere

  double stickingEta() const { return inertia * (1 + tangential_sticking) / (2 * (1 + inertia)); }

  // The coefficients A (tangential part, without <1 - e_n^2>/4), B, C at a temperature ratio
  // R >= 0 and momentum-averaged (1 + e_n) = phi_p.
  template <class S>
  void coefficients(const S& ratio, const S& phi_p, S& A_t, S& B, S& C) const {
    using std::sqrt;
    const double q = inertia, eta0 = stickingEta();
    const S kappa = friction * phi_p / (2 * eta0);
    const S lambda = kappa * sqrt(q / (q + ratio));
    const S c0 = lambda / sqrt(1.0 + lambda * lambda);
    const S eta1 = eta0 * c0;
    const S eta2sq = 2 * eta0 * eta0 * c0 * c0 / (1.0 + c0);
    A_t = 0.5 * (eta1 - eta2sq);
    B = eta2sq / (2 * q);
    C = (eta1 - eta2sq / q) / (2 * q);
  }

  // The collisional rates per unit mass: translational (the tangential part only; the normal
  // loss is D_c) and rotational temperature, m^2/s^3.
  template <class S>
  void rates(const S& nu, const S& g2, const S& phi_p, const S& theta, const S& theta_r,
             double sigma, S& translational, S& rotational) const {
    using std::sqrt;
    S A_t, B, C;
    coefficients(S(theta_r / theta), phi_p, A_t, B, C);
    const S G = 16.0 * nu * g2 / (std::sqrt(std::numbers::pi) * sigma);
    const S root = sqrt(theta);
    translational = G * root * (-A_t * theta + B * theta_r);
    rotational = 2.0 * G * root * (B * theta - C * theta_r);
  }
};

}  // namespace granwave::hydro
