#pragma once
// Maxwell-averaged restitution closures for velocity-dependent normal restitution
// (docs/hydro.md, "Closures"; local-Maxwellian, leading-Sonine closure).
//
// For a Maxwellian at temperature T = m theta, the collision-rate-weighted distribution of the
// normal impact speed u of a colliding pair is P(u) ~ u exp(-u^2/(4 theta)) in every d, and a
// particle hits a flat wall with normal speed v at rate ~ v exp(-v^2/(2 theta)). The constant-e
// factors of kinetic theory are replaced by
//
//     Phi_W(theta)      = <1 - e^2>
//                       = (1/(8 theta^2)) int_0^inf u^3 exp(-u^2/(4 theta)) (1 - e(u)^2) du
//     Phi_P(theta)      = <1 + e>_P
//                       = (1/(2 sqrt(pi))) theta^{-3/2}
//                         int_0^inf u^2 exp(-u^2/(4 theta)) (1 + e(u)) du
//     Phi_W^wall(theta) = (1/(2 theta^2)) int_0^inf v^3 exp(-v^2/(2 theta)) (1 - e(v)^2) dv
//     e_eff(theta)      = sqrt(1 - Phi_W)
//
// Phi_W is the energy-weighted average (energy lost per collision (m/4)(1 - e^2) u^2), Phi_P
// the momentum-weighted one (momentum transfer (m/2)(1 + e) u). Closed forms for the three
// laws of the paper (particles/Restitution.hpp), with w = 4 for pairs and w = 2 for walls:
//
//   constant e:                Phi_W = Phi_W^wall = 1 - e^2,   Phi_P = 1 + e
//   dry e = 1 - kappa u^{1/5}: Phi_W = 2 kappa Gamma(21/10) (w theta)^{1/10}
//                                      - kappa^2 Gamma(11/5) (w theta)^{1/5}
//                              Phi_P = 2 - kappa [Gamma(8/5)/Gamma(3/2)] (4 theta)^{1/10}
//   wet e = e_inf (1 - v_c/u) for u >= v_c, else 0, with y = v_c / sqrt(w theta):
//                              Phi_W = 1 - e_inf^2 [exp(-y^2) - sqrt(pi) y erfc(y)]
//                              Phi_P = 1 + e_inf erfc(y_pair)
//
// The theta-derivatives are analytic (no finite differences):
//   dry: dPhi_P/dtheta = -(kappa/10) [Gamma(8/5)/Gamma(3/2)] (4 theta)^{1/10} / theta
//        dPhi_W/dtheta = [ (kappa/5) Gamma(21/10) (w theta)^{1/10}
//                          - (kappa^2/5) Gamma(11/5) (w theta)^{1/5} ] / theta
//   wet: dPhi_P/dtheta = e_inf y exp(-y^2) / (sqrt(pi) theta)
//        dPhi_W/dtheta = -e_inf^2 sqrt(pi) erfc(y) y / (2 theta)
//        (d/dy [exp(-y^2) - sqrt(pi) y erfc(y)] = -sqrt(pi) erfc(y), dy/dtheta = -y/(2 theta))
//
// Domain: theta > 0 (m^2/s^2). At theta <= 0 the Phi's return their theta -> 0+ limits
// (dry: Phi_W = 0, Phi_P = 2; wet: Phi_W = 1, Phi_P = 1) and the derivatives theirs (wet: 0;
// dry: infinite, since Phi ~ theta^{1/10}).
// The dry law is clamped to e >= 0 at the particle level (u > kappa^-5, 1e5 m/s for
// kappa = 0.1); the closed forms ignore the clamp, a relative error below
// exp(-kappa^-10 / (4 theta)).
//
// A closed set of three laws: a value type with a switch, like particles/Restitution.hpp.
#include "hydro/Scalar.hpp"

namespace granwave::hydro {

// The averaged factors at one temperature, as the transport closures use them: (1 - e^2) ->
// phi_w, (1 + e) -> phi_p. The default is elastic.
struct RestitutionAverages {
  double phi_w = 0.0;  // <1 - e^2>, pair collisions
  double phi_p = 2.0;  // <1 + e>_P, pair collisions
  // e_eff = sqrt(1 - phi_w), used for the kinetic (nu_eta*, nu_kappa*-type) factors.
  double effectiveRestitution() const;
};

// Every average the discrete operator needs at one temperature, with the theta-derivatives
// its exact Jacobian needs, from one evaluation of the closed forms: the dry law's powers are
// all (w theta)^(1/10) = w^(1/10) theta^(1/10) and its square, so one pow serves the six of
// them; the wet law needs erfc and exp at the pair and at the wall argument once each.
struct MaxwellAverages {
  double phi_w = 0, dphi_w = 0;        // <1 - e^2>, pairs, and d/dtheta
  double phi_p = 2, dphi_p = 0;        // <1 + e>_P, pairs, and d/dtheta
  double d2phi_p = 0;                  // d^2 Phi_P/dtheta^2
  double phi_wall = 0, dphi_wall = 0;  // <1 - e^2> at a wall, and d/dtheta
};

// The same on a differentiable scalar (hydro/Scalar.hpp): the derivative of dphi_p is d2phi_p.
template <class S>
struct MaxwellAveragesOf {
  S phi_w, phi_p, dphi_p, phi_wall;
};

class RestitutionClosure {
 public:
  enum class Law { Constant, Dry, Wet };

  // Elastic (constant e = 1).
  RestitutionClosure() = default;
  // 0 <= e <= 1.
  static RestitutionClosure constant(double e);
  // e(u) = 1 - kappa u^{1/5}, kappa >= 0 in s^{1/5} m^{-1/5} (paper: 0.1).
  static RestitutionClosure dry(double kappa);
  // e(u) = e_inf (1 - v_c/u) for u >= v_c, else 0; 0 <= e_inf <= 1, v_c >= 0 in m/s
  // (paper: e_inf = 0.91, v_c = St_c / q = 0.0698 m/s).
  static RestitutionClosure wet(double e_inf, double onset_velocity);

  // The particle-level law e(u) at normal impact speed u >= 0 (m/s).
  double coefficient(double u) const;

  double phiW(double theta) const;                  // <1 - e^2>, pairs
  double phiP(double theta) const;                  // <1 + e>_P, pairs
  double phiWall(double theta) const;               // <1 - e^2>, particle-wall
  double dPhiWdTheta(double theta) const;           // s^2/m^2
  double dPhiPdTheta(double theta) const;           // s^2/m^2
  double dPhiWallDTheta(double theta) const;        // s^2/m^2
  double effectiveRestitution(double theta) const;  // sqrt(1 - Phi_W)
  RestitutionAverages averages(double theta) const { return {phiW(theta), phiP(theta)}; }
  // d^2 Phi_P / d theta^2, s^4/m^4: the sound speed contains dPhi_P/dtheta, and the exact
  // Jacobian its derivative.
  //   dry: 0.09 kappa [Gamma(8/5)/Gamma(3/2)] (4 theta)^{1/10} / theta^2
  //   wet: -e_inf y exp(-y^2) (3/2 - y^2) / (sqrt(pi) theta^2)
  double d2PhiPdTheta2(double theta) const;

  // The same factors at a temperature carried as a differentiable scalar (hydro/Scalar.hpp):
  // value and derivative from the closed forms above.
  template <class S>
  S phiW(const S& theta) const {
    return chain(theta, phiW(value(theta)), dPhiWdTheta(value(theta)));
  }
  template <class S>
  S phiP(const S& theta) const {
    return chain(theta, phiP(value(theta)), dPhiPdTheta(value(theta)));
  }
  template <class S>
  S phiWall(const S& theta) const {
    return chain(theta, phiWall(value(theta)), dPhiWallDTheta(value(theta)));
  }
  template <class S>
  S dPhiPdTheta(const S& theta) const {
    return chain(theta, dPhiPdTheta(value(theta)), d2PhiPdTheta2(value(theta)));
  }

  // All of the above at once (MaxwellAverages); equal to the single functions to round-off.
  MaxwellAverages allAverages(double theta) const;
  template <class S>
  MaxwellAveragesOf<S> averagesOf(const S& theta) const {
    const MaxwellAverages a = allAverages(value(theta));
    return {chain(theta, a.phi_w, a.dphi_w), chain(theta, a.phi_p, a.dphi_p),
            chain(theta, a.dphi_p, a.d2phi_p), chain(theta, a.phi_wall, a.dphi_wall)};
  }

  bool operator==(const RestitutionClosure&) const = default;

  Law law() const { return law_; }
  double restitution() const { return e_; }  // e, e_inf (wet), 1 (dry: e(u -> 0))
  double kappa() const { return law_ == Law::Dry ? kappa_ : 0.0; }
  double onsetVelocity() const { return law_ == Law::Wet ? v_c_ : 0.0; }

 private:
  RestitutionClosure(Law law, double e, double kappa, double v_c)
      : law_(law), e_(e), kappa_(kappa), v_c_(v_c) {}
  // <1 - e^2> with weight v^3 exp(-v^2/(w theta)); w = 4 pairs, w = 2 walls.
  double lossAverage(double theta, double w) const;
  double lossAverageDerivative(double theta, double w) const;

  Law law_ = Law::Constant;
  double e_ = 1.0;      // e (constant) or e_inf (wet)
  double kappa_ = 0.0;  // dry
  double v_c_ = 0.0;    // wet onset velocity, m/s
};

// The same averages by direct numerical quadrature of the defining integrals above (adaptive
// Simpson in x = u / sqrt(w theta) on [0, 10], split at the wet onset), relative accuracy
// ~1e-12. Independent of the closed forms: for tests and for checking new laws. theta > 0.
double numericalPhiW(const RestitutionClosure& closure, double theta);
double numericalPhiP(const RestitutionClosure& closure, double theta);
double numericalPhiWall(const RestitutionClosure& closure, double theta);

}  // namespace granwave::hydro
