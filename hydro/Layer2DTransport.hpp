#pragma once
// GranularHydro2D's right-hand side, third part: heat conduction and advection along the
// layers. Internal to the 2D operator.
//
// Conduction: q = -kappa grad theta through each interface (normal (-dz/dx, 1) dx: the 1D
// flux with the slope's corrections) and each face (the horizontal gradient at fixed height:
// along the layer less the slope times d(theta)/dz). The two-point part of a flux runs down
// the difference of the two cells it joins; the slope's correction is built from other
// cells' temperatures and can drive heat out of a cell colder than both (a cold, packed
// column beside one that lands: docs/hydro.md, "Conduction on sloped layers"). Each
// correction is therefore weighted by 4 theta_a theta_b / (theta_a + theta_b)^2 of the two
// cells: 1 - delta^2/4 for theta_b = theta_a (1 + delta), so smooth fields keep their
// consistent flux to second order in the jump, while the outflow a correction drives from a
// cell of theta_a -> 0 vanishes with theta_a (about 4 theta_a / theta_b times the
// correction): no cell's temperature reaches zero through conduction (a positivity argument
// in the spirit of the nonlinear two-point fluxes of Le Potier, C. R. Math. 341, 787 (2005)).
//
// Advection: the mass flux F through a face carries the upwinded, limited value of the
// advected field (in s = ln theta for the temperatures, so positive). In the inflow form
// M dphi/dt = sum F_in (phi* - phi) the advected energy M theta is conserved exactly; the
// momenta of the faces (u) and the nodes (w) are advected through their dual cells (half a
// cell on each side: mass fluxes the means of the faces'), and the kinetic energy the upwind
// part removes, -F dv (v* - vbar) >= 0 at each crossing, heats the cells there: advection
// changes no energy.
#include <cmath>

#include "hydro/Layer2DState.hpp"

namespace granwave::hydro::layer2d {

// d(theta)/dz of cell (i, k) along its column (one-sided at the ends, 0 for a single cell).
template <class S>
S verticalGradient(const GranularHydro2D::Workspace<S>& w, int i, int k) {
  const ColumnGrid& g = w.grid;
  if (g.N == 1) return constantLike(w.theta[0], 0.0);
  const int lo = k > 0 ? k - 1 : k, hi = k + 1 < g.N ? k + 1 : k;
  S span = 0.5 * (w.len[g.cell(i, lo)] + w.len[g.cell(i, hi)]);
  for (int m = lo + 1; m < hi; ++m) span += w.len[g.cell(i, m)];
  return (w.theta[g.cell(i, hi)] - w.theta[g.cell(i, lo)]) / span;
}

// The weight of a conduction flux's slope correction between cells of theta a and b.
template <class S>
S correctionWeight(const S& a, const S& b) {
  const S sum = a + b;
  return 4.0 * a * b / (sum * sum);
}

template <class S>
void heatConduction(const StateView<S>& v, GranularHydro2D::Workspace<S>& w) {
  const ColumnGrid& g = w.grid;
  const double dx = v.op.dx();
  for (int i = 0; i < g.Nx; ++i) {
    const int a = g.mirrored(i, -1), b = g.mirrored(i, 1);
    for (int j = 1; j < g.N; ++j) {  // interfaces of column i
      const int c0 = g.cell(i, j - 1), c1 = g.cell(i, j);
      const S kappa = 0.5 * (w.local[c0].kappa_theta + w.local[c1].kappa_theta);
      const S tz = (w.theta[c1] - w.theta[c0]) / (0.5 * (w.len[c0] + w.len[c1]));
      const S ts = (w.theta[g.cell(b, j - 1)] + w.theta[g.cell(b, j)] - w.theta[g.cell(a, j - 1)] -
                    w.theta[g.cell(a, j)]) /
                   (4 * dx);
      const S& zx = w.zx[g.node(i, j)];
      const S Q = -kappa *
                  ((1.0 + zx * zx) * tz - correctionWeight(w.theta[c0], w.theta[c1]) * zx * ts) *
                  dx;  // upward
      w.heat[c0] -= Q;
      w.heat[c1] += Q;
    }
    if (v.op.wallFace(i)) continue;
    const int r = g.right(i);
    for (int k = 0; k < g.N; ++k) {  // faces to the right of column i
      const int c = g.cell(i, k), cr = g.cell(r, k);
      const S kappa = 0.5 * (w.local[c].kappa_theta + w.local[cr].kappa_theta);
      const S slope = (w.zc[cr] - w.zc[c]) / dx;
      const S tz = 0.5 * (verticalGradient(w, i, k) + verticalGradient(w, r, k));
      const S Q = -kappa *
                  ((w.theta[cr] - w.theta[c]) / dx -
                   correctionWeight(w.theta[c], w.theta[cr]) * slope * tz) *
                  w.h[c];  // rightward
      w.heat[c] -= Q;
      w.heat[cr] += Q;
    }
  }
}

// The smooth switch width of a mass flux (kg/s per unit depth): rho_max u_noise sigma.
inline double fluxWidth(const GranularHydro2D& op) {
  return op.cellRegularisation().rho_max * op.cellRegularisation().u_width * op.model().sigma;
}

// The temperatures (and rotational temperatures) carried by the mass fluxes.
template <class S>
void temperatureAdvection(const StateView<S>& v, GranularHydro2D::Workspace<S>& w) {
  using std::exp;
  const ColumnGrid& g = w.grid;
  const double unit = v.op.thetaUnit(), width = fluxWidth(v.op);
  for (int i = 0; i < g.Nx; ++i) {
    if (v.op.wallFace(i)) continue;
    const int a = g.mirrored(i, -1), r = g.mirrored(i, 1), b = g.mirrored(i, 2);
    for (int k = 0; k < g.N; ++k) {
      const S& F = w.flux[g.cell(i, k)];
      const int c = g.cell(i, k), cr = g.cell(r, k);
      for (int field = 0; field < (v.op.rough() ? 2 : 1); ++field) {
        auto s = [&](int col) -> const S& { return field == 0 ? v.s(col, k) : v.sr(col, k); };
        const S L = faceValue(s(a), s(i), s(r), 1e-12);
        const S R = faceValue(s(b), s(r), s(i), 1e-12);
        const S carried = unit * exp(upwind(F, L, R, width));
        std::vector<S>& heat = field == 0 ? w.heat : w.heat_r;
        heat[c] -= F * (carried - unit * exp(s(i)));
        heat[cr] += F * (carried - unit * exp(s(r)));
      }
    }
  }
}

// u of face position p of layer k (faces -1 and Nx - 1 are side walls, u = 0, mirrored
// oddly beyond them; periodic: wrapped).
template <class S>
S faceVelocity(const StateView<S>& v, const ColumnGrid& g, int p, int k) {
  if (g.periodic) return v.u(((p % g.Nx) + g.Nx) % g.Nx, k);
  if (p < -1) return -faceVelocity(v, g, -2 - p, k);
  if (p > g.Nx - 1) return -faceVelocity(v, g, 2 * (g.Nx - 1) - p, k);
  return v.u(p, k);
}

// The horizontal momenta of the faces, through the centres of the cells between them.
template <class S>
void horizontalMomentumAdvection(const StateView<S>& v, GranularHydro2D::Workspace<S>& w) {
  const ColumnGrid& g = w.grid;
  const double width = fluxWidth(v.op),
               width2 = v.op.cellRegularisation().u_width * v.op.cellRegularisation().u_width;
  for (int i = 0; i < g.Nx; ++i) {
    const int l = g.left(i);
    const bool left_moves = l >= 0, right_moves = !v.op.wallFace(i);
    if (!left_moves && !right_moves) continue;
    for (int k = 0; k < g.N; ++k) {
      const S G = 0.5 * ((l >= 0 ? w.flux[g.cell(l, k)] : zeroLike(v)) + w.flux[g.cell(i, k)]);
      const S uL = faceVelocity(v, g, i - 1, k), uR = faceVelocity(v, g, i, k);
      const S L = faceValue(faceVelocity(v, g, i - 2, k), uL, uR, width2);
      const S R = faceValue(faceVelocity(v, g, i + 1, k), uR, uL, width2);
      const S carried = upwind(G, L, R, width);
      if (left_moves) w.fu[g.cell(l, k)] -= G * (carried - uL);
      if (right_moves) w.fu[g.cell(i, k)] += G * (carried - uR);
      w.heat[g.cell(i, k)] -= G * (uR - uL) * (carried - 0.5 * (uL + uR));
    }
  }
}

// The vertical momenta of the nodes, through the faces between columns.
template <class S>
void verticalMomentumAdvection(const StateView<S>& v, GranularHydro2D::Workspace<S>& w) {
  const ColumnGrid& g = w.grid;
  const double width = fluxWidth(v.op),
               width2 = v.op.cellRegularisation().u_width * v.op.cellRegularisation().u_width;
  for (int i = 0; i < g.Nx; ++i) {
    if (v.op.wallFace(i)) continue;
    const int a = g.mirrored(i, -1), r = g.mirrored(i, 1), b = g.mirrored(i, 2);
    for (int j = 0; j <= g.N; ++j) {
      const S H = interfaceFlux(w, i, j);  // the node's mass flux, as its drift's
      const int count = (j > 0 ? 1 : 0) + (j < g.N ? 1 : 0);
      const S& wL = v.w(i, j);
      const S& wR = v.w(r, j);
      const S L = faceValue(v.w(a, j), wL, wR, width2);
      const S R = faceValue(v.w(b, j), wR, wL, width2);
      const S carried = upwind(H, L, R, width);
      w.fw[g.node(i, j)] -= H * (carried - wL);
      w.fw[g.node(r, j)] += H * (carried - wR);
      const S heat = -H * (wR - wL) * (carried - 0.5 * (wL + wR)) / (2.0 * count);
      for (int k = j - 1; k <= j; ++k)
        if (k >= 0 && k < g.N) w.heat[g.cell(i, k)] += heat, w.heat[g.cell(r, k)] += heat;
    }
  }
}

}  // namespace granwave::hydro::layer2d
