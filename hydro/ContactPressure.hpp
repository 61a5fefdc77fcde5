#pragma once
// The contact pressure that carries a cold, packed layer (docs/hydro.md, "Dense limit").
//
// The kinetic-collisional pressure n T (1 + Phi_P nu g2) vanishes with the temperature at any
// area fraction below close packing, so a layer at rest on the plate (or landing on it and
// cooling) has nothing to hold its weight: it packs until the discrete operator breaks. In
// dense granular flow this load is carried by enduring contacts, modelled in two-fluid and
// kinetic-theory codes by a rate-independent frictional/contact pressure that switches on at
// a minimum area fraction and diverges at the maximum one (Johnson & Jackson, J. Fluid Mech.
// 176, 67 (1987): p_f = Fr (nu - nu_min)^n / (nu_max - nu)^p). Here, for disks,
//
//     p_c(nu) = P_c [ (nu - nu_min)_+ / (nu_max - nu) ]^2
//
// with nu_min the random close packing of disks (0.82), nu_max hexagonal close packing
// (0.9069), and P_c = rho_cp g sigma, the weight per unit length of one close-packed row of
// particles: a layer of k rows at rest then packs to nu = (nu_min + sqrt(k) nu_max)/(1 + sqrt(k))
// at its base (0.88 for the paper's 10 rows). p = 2 > 1 makes the stored energy
// int p_c/rho^2 drho diverge at nu_max, so no finite kinetic energy packs past it.
// The pressure is elastic (a function of density only): it enters the momentum balance, and
// its work is exchanged reversibly with the flow's kinetic energy, never with the granular
// temperature (docs/hydro.md, "Internal energy").
#include <cmath>

#include "hydro/PairCorrelation.hpp"
#include "hydro/Scalar.hpp"

namespace granwave::hydro {

struct ContactPressure {
  double onset = 0.82;                            // nu_min
  double close_packing = kHexagonalClosePacking;  // nu_max
  double scale = 0.0;                             // P_c, N/m; 0 = no contact pressure
  static constexpr double kOnsetWidth = 2e-3;     // (nu - nu_min)_+ blended over +-this

  template <class S>
  S pressure(const S& nu) const {
    if (scale == 0.0) return constantLike(nu, 0.0);
    const S r = blendedMax(S(nu - onset), 0.0, kOnsetWidth) / (close_packing - nu);
    return scale * r * r;
  }
  // dp_c/dnu.
  template <class S>
  S derivative(const S& nu) const {
    if (scale == 0.0) return constantLike(nu, 0.0);
    const S d = nu - onset;
    const S x = blendedMax(d, 0.0, kOnsetWidth);
    S dx = constantLike(nu, value(d) >= kOnsetWidth ? 1.0 : 0.0);
    if (std::abs(value(d)) < kOnsetWidth) dx = (d + kOnsetWidth) / (2.0 * kOnsetWidth);
    const S y = close_packing - nu;
    return 2.0 * scale * (x / y) * (dx / y + x / (y * y));
  }
};

}  // namespace granwave::hydro
