#pragma once
// GranularHydro2D's right-hand side, first part: the cells as the closures see them, the
// layer geometry between columns (face heights, interface slopes, the interfaces' vertical
// drift) and the horizontal mass fluxes. Internal to the 2D operator.
#include <cmath>

#include "hydro/Layer2DWorkspace.hpp"

namespace granwave::hydro::layer2d {

// The unknown at (column i, index) of the state, with the operator's layout.
template <class S>
struct StateView {
  const GranularHydro2D& op;
  const S* U;
  const S& z(int i, int j) const { return U[op.heightIndex(i, j)]; }
  const S& w(int i, int j) const { return U[op.velocityIndex(i, j)]; }
  const S& s(int i, int k) const { return U[op.temperatureIndex(i, k)]; }
  const S& sr(int i, int k) const { return U[op.rotationIndex(i, k)]; }
  // u and Phi of face (i, k); a side wall's are exactly 0.
  S u(int i, int k) const {
    return i < 0 || op.wallFace(i) ? constantLike(U[0], 0.0) : U[op.horizontalVelocityIndex(i, k)];
  }
  S phi(int i, int k) const {
    return i < 0 || op.wallFace(i) ? constantLike(U[0], 0.0) : U[op.fluxIndex(i, k)];
  }
};

// A constant of the state's scalar type.
template <class S>
S zeroLike(const StateView<S>& v) {
  return constantLike(v.U[0], 0.0);
}

// Cells: geometry, mass, what the closures see, and the closures; rough particles' exchange.
template <class S>
void cellStates(const StateView<S>& v, GranularHydro2D::Workspace<S>& w) {
  using std::exp;
  const GranularHydro2D& op = v.op;
  const ColumnGrid& g = w.grid;
  const CellRegularisation& reg = op.cellRegularisation();
  const ConstitutiveModel& model = op.model();
  const double dx = op.dx();
  for (int i = 0; i < g.Nx; ++i)
    for (int k = 0; k < g.N; ++k) {
      const int c = g.cell(i, k);
      const S mu = op.initialCellMass()[c] + (v.phi(g.left(i), k) - v.phi(i, k)) / dx;
      w.mass[c] = smoothPositivePart(mu, op.massFloor());
      const EffectiveCell<S> e =
          effectiveCell(reg, w.mass[c], op.thetaUnit(), v.z(i, k), v.z(i, k + 1), v.s(i, k));
      w.len[c] = e.length;
      w.rho[c] = w.mass[c] / e.length;
      w.rho_eff[c] = e.rho;
      w.theta[c] = e.theta;
      w.zc[c] = 0.5 * (v.z(i, k) + v.z(i, k + 1));
      w.local[c] = model.evaluate(e.rho, e.theta);
      w.heat[c] = zeroLike(v);
      w.heat_r[c] = zeroLike(v);
      if (!op.rough()) continue;
      const S spin = op.thetaUnit() * exp(v.sr(i, k)) + reg.theta_min;
      const S nu = e.rho * (model.diskArea() / model.mass);
      model.rough.rates(nu, w.local[c].g2, w.local[c].phi_p, e.theta, spin, model.sigma,
                        w.exchange[c], w.spin[c]);
    }
}

// The layer between columns: each face's height (the mean of its two cells' lengths), each
// node's interface slope dz/dx (central; mirrored at a side wall) and the slope across each
// face (between the node's column and the next).
template <class S>
void layerGeometry(const StateView<S>& v, GranularHydro2D::Workspace<S>& w) {
  const ColumnGrid& g = w.grid;
  const double dx = v.op.dx();
  for (int i = 0; i < g.Nx; ++i) {
    const int r = g.right(i), l = g.left(i);
    for (int k = 0; k < g.N; ++k)
      w.h[g.cell(i, k)] =
          r < 0 ? zeroLike(v) : S(0.5 * (w.len[g.cell(i, k)] + w.len[g.cell(r, k)]));
    for (int j = 0; j <= g.N; ++j) {
      const S& zr = v.z(r < 0 ? i : r, j);
      const S& zl = v.z(l < 0 ? i : l, j);
      w.zx[g.node(i, j)] = (zr - zl) / (2 * dx);
      w.face_slope[g.node(i, j)] = r < 0 ? zeroLike(v) : S((zr - v.z(i, j)) / dx);
    }
  }
}

// The mass flux through face column f at the height of interface j: half of each adjoining
// layer's (one layer at the plate and at the free surface).
template <class S>
S interfaceFlux(const GranularHydro2D::Workspace<S>& w, int f, int j) {
  const ColumnGrid& g = w.grid;
  if (j == 0) return 0.5 * w.flux[g.cell(f, 0)];
  if (j == g.N) return 0.5 * w.flux[g.cell(f, g.N - 1)];
  return 0.5 * (w.flux[g.cell(f, j - 1)] + w.flux[g.cell(f, j)]);
}

// The sum of node (i, j)'s two cells' masses per unit width (the one cell's at the plate and
// at the free surface): the node's mass is dx/2 times it.
template <class S>
S nodeMassSum(const GranularHydro2D::Workspace<S>& w, int i, int j) {
  const ColumnGrid& g = w.grid;
  if (j == 0) return w.mass[g.cell(i, 0)];
  if (j == g.N) return w.mass[g.cell(i, g.N - 1)];
  return w.mass[g.cell(i, j - 1)] + w.mass[g.cell(i, j)];
}

// Each node's vertical drift, the rate at which flow along a sloped interface moves it (the
// interfaces are material: dz/dt = w - drift):
//   drift_ij = (Q_ij s_ij + Q_lj s_lj) / (mu_below + mu_above),
// Q the mass flux at the interface through each of the node's two faces (interfaceFlux), s the
// slope across it. Why this form. Mass F crossing a face between columns whose cells sit at
// different heights changes its potential energy by g F dz_c; summed over the faces that is
// g dx sum Q s over (face, interface) pairs, and the nodes (of mass dx (mu_b + mu_a)/2) moving
// down by their drift change it by -g sum m drift: with this drift the two are equal in every
// state, so the horizontal flow does no work against gravity (as in the continuum, where
// flow at a fixed height leaves the potential energy alone) and the operator's energy rates
// are the lab-frame energy's derivative (tests/hydro/Hydro2DEnergyBudgetTest), up to the
// smooth switches: F's upwind switch over |u| < u_width (F is not quite linear in u) and the
// mass floor. For a layer of uniform density and cell length (F = mu u) it is 0.5 sum U_f s_f,
// the kinematic u dz/dx face by face (to leading order otherwise). A near-empty cell with
// inflow from a full neighbour gets a large drift, Q/mu: the remap keeps cells from emptying.
// Face by face, not the mean velocity times the central slope: a central slope is blind
// to interfaces whose heights alternate from column to column, and with it a two-column mode
// had no restoring force (docs/hydro.md, "Interfaces between columns").
template <class S>
void interfaceDrift(GranularHydro2D::Workspace<S>& w) {
  const ColumnGrid& g = w.grid;
  for (int i = 0; i < g.Nx; ++i) {
    const int l = g.left(i);
    for (int j = 0; j <= g.N; ++j) {
      S moved = interfaceFlux(w, i, j) * w.face_slope[g.node(i, j)];
      if (l >= 0) moved += interfaceFlux(w, l, j) * w.face_slope[g.node(l, j)];
      w.drift[g.node(i, j)] = moved / nodeMassSum(w, i, j);
    }
  }
}

// The van Leer-limited value of a field at the face between a and b from a's side:
// a + slope(a)/2, slope(a) from (before, a, b). Within [0, 2a] for a positive field.
template <class S>
S faceValue(const S& before, const S& a, const S& b, double width2) {
  return a + 0.5 * limitedSlope(S(a - before), S(b - a), width2);
}

// The value carried through a face by a flux F from the left (L) and right (R) reconstructions:
// the upwind one, switched smoothly over |F| < width.
template <class S>
S upwind(const S& F, const S& L, const S& R, double width) {
  return 0.5 * (L + R) - 0.5 * (F / smoothAbs(F, width)) * (R - L);
}

// The mass fluxes F_ik = h u rho* through the faces (a side wall's is 0), rho* the upwinded,
// limited density of the layer, and their derivatives by u (the drift's, interfaceDrift).
template <class S>
void massFluxes(const StateView<S>& v, GranularHydro2D::Workspace<S>& w) {
  const ColumnGrid& g = w.grid;
  const CellRegularisation& reg = v.op.cellRegularisation();
  const double width2 = 1e-12 * reg.rho_max * reg.rho_max;
  for (int i = 0; i < g.Nx; ++i) {
    if (v.op.wallFace(i)) {
      for (int k = 0; k < g.N; ++k) w.flux[g.cell(i, k)] = w.flux_du[g.cell(i, k)] = zeroLike(v);
      continue;
    }
    const int a = g.mirrored(i, -1), r = g.mirrored(i, 1), b = g.mirrored(i, 2);
    for (int k = 0; k < g.N; ++k) {
      const S& rl = w.rho[g.cell(a, k)];
      const S& r0 = w.rho[g.cell(i, k)];
      const S& r1 = w.rho[g.cell(r, k)];
      const S& r2 = w.rho[g.cell(b, k)];
      const S L = faceValue(rl, r0, r1, width2);
      const S R = faceValue(r2, r1, r0, width2);
      const S u = v.u(i, k);
      const S speed = smoothAbs(u, reg.u_width);
      w.flux[g.cell(i, k)] = w.h[g.cell(i, k)] * (0.5 * u * (L + R) - 0.5 * speed * (R - L));
      w.flux_du[g.cell(i, k)] = w.h[g.cell(i, k)] * (0.5 * (L + R) - 0.5 * (u / speed) * (R - L));
    }
  }
}

}  // namespace granwave::hydro::layer2d
