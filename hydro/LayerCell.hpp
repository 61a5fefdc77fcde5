#pragma once
// What the continuum operators (GranularHydro1D, GranularHydro2D) share of a cell and of a
// wall: the cell as the closures see it (the packing map and the floors, docs/hydro.md,
// "Admissible states") and the unilateral contact of a boundary node with the plate or the lid
// (docs/hydro.md, "Walls"). One definition, so that a flat 2D layer is the 1D layer exactly.
#include <cmath>

#include "hydro/ConstitutiveModel.hpp"
#include "hydro/HydroGeometry.hpp"
#include "hydro/Scalar.hpp"

namespace granwave::hydro {

// The scales of the regularisations, fixed by an operator at construction: close-packed
// density, packing width (kg/m^2), length floor (m), temperature floor (m^2/s^2), velocity
// noise (m/s) and the wall contact's stress scale P_c (N/m).
struct CellRegularisation {
  double rho_max, packing_width, length_floor, theta_min, u_width, contact_scale;
};

// The cell as the closures see it: its length floored smoothly at length_floor (tangled
// iterates), its density mass/length mapped through rho_eff = rho_max - d s((rho_max - rho)/d),
// s(x) = (x + sqrt(x^2 + 4))/2 (below close packing and equal to rho to d^2/(rho_max - rho)),
// and its temperature theta + theta_min, theta = theta_unit exp(s).
template <class S>
struct EffectiveCell {
  S rho, length, theta;
};
template <class S, class Mass>
EffectiveCell<S> effectiveCell(const CellRegularisation& reg, const Mass& mass, double theta_unit,
                               const S& z0, const S& z1, const S& s) {
  using std::exp;
  using std::sqrt;
  const S length = smoothPositivePart(S(z1 - z0), reg.length_floor);
  const S gap = (reg.rho_max - mass / length) / reg.packing_width;
  // s(x) = (x + sqrt(x^2 + 4))/2 = 2/(sqrt(x^2 + 4) - x): the second form keeps its digits
  // when the cell is packed past close packing (x << 0), where the first cancels to 0.
  const S map = value(gap) >= 0 ? S(0.5 * (gap + sqrt(gap * gap + 4.0)))
                                : S(2.0 / (sqrt(gap * gap + 4.0) - gap));
  const S rho = reg.rho_max - reg.packing_width * map;
  return {rho, length, S(theta_unit * exp(s) + reg.theta_min)};
}

// The wall contact: the elastic stress of the penetration p = (r - x)_+ (x = gap/sigma) and
// the contact indicator p^2/(p^2 + p_1^2), both smooth.
template <class S>
struct WallContact {
  S elastic, stiffness, indicator;  // stress, d(stress)/d(penetration) per metre, in contact
};
template <class S>
WallContact<S> wallContact(const S& gap, double sigma, double scale, const HydroRegularisation& n) {
  const double r = n.wall_contact_range, p0 = n.wall_contact_stiffness;
  const S pen = smoothPositivePart(S(r - gap / sigma), 1e-3 * r);
  const S k = pen / p0;
  return {scale * k * k * k, 3.0 * scale * k * k / (p0 * sigma),
          pen * pen / (pen * pen + 0.01 * p0 * p0)};
}

// The elastic energy stored in a wall contact at this gap (J/m of wall): the integral of the
// elastic stress from the gap out to the end of the contact's range (Simpson's rule; the
// stress is a smooth cubic of the penetration there).
inline double wallContactEnergy(double gap, double sigma, double scale,
                                const HydroRegularisation& n) {
  const double end = 1.2 * n.wall_contact_range * sigma;
  if (gap >= end) return 0;
  const int steps = 200;
  const double h = (end - gap) / steps;
  double sum = 0;
  for (int k = 0; k <= steps; ++k)
    sum += (k == 0 || k == steps ? 1 : (k % 2 ? 4 : 2)) *
           wallContact(gap + k * h, sigma, scale, n).elastic;
  return sum * h / 3;
}

// The stress a wall exerts on the boundary node next to it, and the power its dashpot and
// collisions take from the wall cell: [stress, dashpot heating, collisional loss, the
// stress's elastic part (minus the derivative of wallContactEnergy by the gap; 0 for a hard
// wall's reaction, which stores no energy)].
template <class S>
struct WallExchange {
  S stress, heating, loss, elastic;
};
// The dashpot makes the boundary node's landing completely inelastic, as the layer's is (its
// particles' bounce is the wall collisions' loss, a separate term): the cell's acoustic
// impedance rho c (no reflected sound) plus critical damping 2 sqrt(k m_node) of the node on
// the contact's stiffness k; it acts while approaching (v times a smooth step in v, exactly 0
// at rest), and its work heats the wall cell. node_mass is per unit width of the wall.
template <class S, class Mass>
WallExchange<S> wallExchange(const S& gap, const S& approach, const LocalState<S>& cell,
                             const S& rho, double sigma, double scale, double u_width,
                             const Mass& node_mass, const HydroRegularisation& numerics) {
  using std::sqrt;
  const WallContact<S> c = wallContact(gap, sigma, scale, numerics);
  const S step = 0.5 * (1.0 + approach / smoothAbs(approach, u_width));
  const S damping = rho * cell.sound_speed + 2.0 * sqrt(c.stiffness * node_mass + 1e-30);
  const S dashpot = damping * approach * step * c.indicator;
  return {c.elastic + dashpot, dashpot * approach, c.indicator * cell.wall_loss * cell.p_kinetic,
          c.elastic};
}

}  // namespace granwave::hydro
