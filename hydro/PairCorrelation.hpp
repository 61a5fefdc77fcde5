#pragma once
// Pair correlation of hard disks at contact, g2(nu), nu = n pi sigma^2/4 the area fraction
// (docs/hydro.md, "Dense limit"). Two forms:
//
//  Henderson (1975), Mol. Phys. 30, 971: Z = p/(n T) = (1 + nu^2/8)/(1 - nu)^2, so
//     g2 = (Z - 1)/(2 nu) = (1 - 7 nu/16)/(1 - nu)^2,  dg2/dnu = (25 - 7 nu)/(16 (1 - nu)^3).
//     Accurate for the fluid; finite up to nu = 1, beyond hexagonal close packing
//     nu_hcp = pi/(2 sqrt 3) = 0.9069 (g2 = 69.6 there), so it cannot stop a cold layer from
//     packing past close packing.
//
//  Luding's global equation of state for disks, S. Luding, Phys. Rev. E 63, 042201 (2001):
//     with P = Z - 1 = 2 nu g2, P = P_4 + m(nu) [P_dense - P_4], merging the fluid (Henderson
//     with the fourth virial correction) and the free-volume form of the crystal, which
//     diverges at close packing nu_max as Z -> 2 nu_max/(nu_max - nu) (Salsburg & Wood,
//     J. Chem. Phys. 37, 798 (1962)):
//       P_4     = 2 nu g_4,   g_4 = (1 - 7 nu/16)/(1 - nu)^2 - nu^3/(128 (1 - nu)^4)
//       P_dense = 2 nu_max/(nu_max - nu) h(nu_max - nu) - 1,   h(x) = 1 + c1 x + c3 x^3
//       m(nu)   = 1/(1 + exp(-(nu - nu_c)/m0))
//     with nu_max = nu_hcp, c1 = -0.04, c3 = 3.25, nu_c = 0.699, m0 = 0.0111: the merge sits
//     in the liquid-hexatic coexistence of hard disks (0.700-0.716, Bernard & Krauth, PRL 107,
//     155704 (2011)). Its width matters for hydrodynamics: a merge much sharper than m0 ~ 0.01
//     makes the pressure n T Z fall with density across the coexistence region (a van der
//     Waals loop: negative compressibility, imaginary sound speed), which no PDE can carry;
//     with m0 = 0.0111 d(nu Z)/dnu > 0 everywhere. tests/hydro check that, Z against Engel et
//     al., PRE 87, 042134 (2013) at 0.700 and 0.720, and the free-volume limit.
//
// Both are templates on the scalar type (hydro/Scalar.hpp) so the Jacobian is exact.
#include <cmath>
#include <numbers>

#include "hydro/Scalar.hpp"

namespace granwave::hydro {

inline constexpr double kHexagonalClosePacking = std::numbers::pi / (2.0 * std::numbers::sqrt3);

// Henderson g2(nu), 0 <= nu < 1.
double pairCorrelation(double nu);
// dg2/dnu of the Henderson form, 0 <= nu < 1.
double pairCorrelationDerivative(double nu);

struct PairCorrelation {
  enum class Form { Henderson, Luding };
  Form form = Form::Luding;
  double close_packing = kHexagonalClosePacking;  // nu_max of Luding's form

  template <class S>
  S g2(const S& nu) const;
  template <class S>
  S dg2(const S& nu) const;  // dg2/dnu
  // Both at once (one exponential for Luding's form).
  template <class S>
  void g2WithDerivative(const S& nu, S& g2, S& dg2) const;
  // The area fraction beyond which no state exists (Henderson: 1; Luding: nu_max).
  double limit() const { return form == Form::Henderson ? 1.0 : close_packing; }
};

namespace detail {

template <class S>
S hendersonG2(const S& nu) {
  const S h = 1.0 - nu;
  return (1.0 - 7.0 * nu / 16.0) / (h * h);
}
template <class S>
S hendersonDG2(const S& nu) {
  const S h = 1.0 - nu;
  return (25.0 - 7.0 * nu) / (16.0 * h * h * h);
}

struct LudingConstants {
  double c1 = -0.04, c3 = 3.25, nu_c = 0.699, m0 = 0.0111;
};

// g2 and dg2/dnu of Luding's global form, g2 = g_4 + m (P_dense - P_4)/(2 nu) (written so,
// not as P/(2 nu), to keep precision in the dilute gas).
template <class S>
void ludingG2(const S& nu, double nu_max, S& g2, S& dg2) {
  using std::exp;
  const LudingConstants k;
  const S h = 1.0 - nu;
  const S h4 = h * h * h * h;
  const S g4 = hendersonG2(nu) - nu * nu * nu / (128.0 * h4);
  const S dg4 = hendersonDG2(nu) - (3.0 * nu * nu * h + 4.0 * nu * nu * nu) / (128.0 * h4 * h);
  const S p4 = 2.0 * nu * g4;
  const S dp4 = 2.0 * g4 + 2.0 * nu * dg4;
  const S x = nu_max - nu;
  const S hx = 1.0 + k.c1 * x + k.c3 * x * x * x;
  const S dhx = -(k.c1 + 3.0 * k.c3 * x * x);  // d h(x)/d nu
  const S pd = 2.0 * nu_max / x * hx - 1.0;
  const S dpd = 2.0 * nu_max / (x * x) * hx + 2.0 * nu_max / x * dhx;
  const S em = exp(-(nu - k.nu_c) / k.m0);
  const S m = 1.0 / (1.0 + em);
  const S dm = em / (k.m0 * (1.0 + em) * (1.0 + em));
  const S jump = (pd - p4) / (2.0 * nu);
  g2 = g4 + m * jump;
  dg2 = dg4 + (dm * (pd - p4) + m * (dpd - dp4)) / (2.0 * nu) - m * jump / nu;
}

}  // namespace detail

template <class S>
S PairCorrelation::g2(const S& nu) const {
  if (form == Form::Henderson) return detail::hendersonG2(nu);
  S g, dg;
  detail::ludingG2(nu, close_packing, g, dg);
  return g;
}

template <class S>
S PairCorrelation::dg2(const S& nu) const {
  if (form == Form::Henderson) return detail::hendersonDG2(nu);
  S g, dg;
  detail::ludingG2(nu, close_packing, g, dg);
  return dg;
}

template <class S>
void PairCorrelation::g2WithDerivative(const S& nu, S& g2, S& dg2) const {
  if (form == Form::Henderson) {
    g2 = detail::hendersonG2(nu);
    dg2 = detail::hendersonDG2(nu);
    return;
  }
  detail::ludingG2(nu, close_packing, g2, dg2);
}

}  // namespace granwave::hydro
