#pragma once
// GranularHydro2D's right-hand side, second part: the stresses. One discrete velocity gradient
// per cell (the normal strains G_xx = du/dx, G_zz = dw/dz) and per corner (the shear strain
// gamma = du/dz + dw/dx at the face column and an interface), each linear in the velocities;
// the cells' stress power
//   P = sum_cells A [-(p + q) tr G + eta (G_xx - G_zz)^2 + lambda_b (tr G)^2]
//       + sum_corners A_c eta gamma^2
// (the d = 2 Navier-Stokes dissipation eta |2 S|^2 / 2 + lambda_b (div v)^2 split between the
// points where each strain is compact) heats the cells, and the force on each velocity is
// minus the derivative of that power by it (compatible discretisation: the work of the forces
// is exactly minus the heating). For a layer uniform in x this is the 1D operator's
// Pi = p + q - (lambda_b + eta) dw/dz on the nodes. Also the plate's, the lid's and the side
// walls' contact. Internal to the 2D operator.
#include "hydro/Layer2DState.hpp"

namespace granwave::hydro::layer2d {

// Adds `coefficient` d(drift_ij)/du to the force of every face the drift of node (i, j)
// depends on (Layer2DState.hpp, interfaceDrift: half of each adjoining layer's dF/du times the
// slope across the face, over the node's mass sum).
template <class S>
void scatterNodeDrift(const GranularHydro2D& op, GranularHydro2D::Workspace<S>& w, int i, int j,
                      const S& coefficient) {
  const ColumnGrid& g = w.grid;
  const int l = g.left(i);
  const S per_flux = 0.5 * coefficient / nodeMassSum(w, i, j);
  for (int k = j - 1; k <= j; ++k) {
    if (k < 0 || k >= g.N) continue;
    if (l >= 0)
      w.fu[g.cell(l, k)] += per_flux * w.flux_du[g.cell(l, k)] * w.face_slope[g.node(l, j)];
    if (!op.wallFace(i))
      w.fu[g.cell(i, k)] += per_flux * w.flux_du[g.cell(i, k)] * w.face_slope[g.node(i, j)];
  }
}

// Cell (i, k): its normal strains and, given the multipliers a of dG_xx and b of dG_zz, the
// forces a dG_xx/dv + b dG_zz/dv on the velocities they depend on.
template <class S>
struct CellStrain {
  S xx, zz;
};
template <class S>
CellStrain<S> cellStrain(const StateView<S>& v, const GranularHydro2D::Workspace<S>& w, int i,
                         int k) {
  const ColumnGrid& g = w.grid;
  const int l = g.left(i), c = g.cell(i, k);
  const S& len = w.len[c];
  const S hL = l < 0 ? zeroLike(v) : w.h[g.cell(l, k)];
  const S volume_flux = w.h[c] * v.u(i, k) - hL * v.u(l, k);
  const S metric = w.drift[g.node(i, k + 1)] - w.drift[g.node(i, k)];
  return {volume_flux / (v.op.dx() * len) - metric / len, (v.w(i, k + 1) - v.w(i, k)) / len};
}
template <class S>
void cellStrainForces(const StateView<S>& v, GranularHydro2D::Workspace<S>& w, int i, int k,
                      const S& a, const S& b) {
  const GranularHydro2D& op = v.op;
  const ColumnGrid& g = w.grid;
  const int l = g.left(i), c = g.cell(i, k);
  const S& len = w.len[c];
  const S ax = a / (op.dx() * len);
  if (!op.wallFace(i)) w.fu[c] += ax * w.h[c];
  if (l >= 0) w.fu[g.cell(l, k)] -= ax * w.h[g.cell(l, k)];
  scatterNodeDrift(op, w, i, k + 1, S(-a / len));
  scatterNodeDrift(op, w, i, k, S(a / len));
  w.fw[g.node(i, k + 1)] += b / len;
  w.fw[g.node(i, k)] -= b / len;
}

// Every cell's pressure, artificial viscosity and normal viscous stresses: forces and heating.
template <class S>
void cellStresses(const StateView<S>& v, GranularHydro2D::Workspace<S>& w) {
  const ColumnGrid& g = w.grid;
  const double c2 = v.op.regularisation().quadratic_viscosity;
  const double u_width = v.op.cellRegularisation().u_width;
  for (int i = 0; i < g.Nx; ++i)
    for (int k = 0; k < g.N; ++k) {
      const int c = g.cell(i, k);
      const CellStrain<S> G = cellStrain(v, w, i, k);
      const LocalState<S>& L = w.local[c];
      const S tr = G.xx + G.zz, dev = G.xx - G.zz;
      // The 1D velocity jump l tr G: q = rho c2 (l tr G)^2 while compressing (1D: du < 0).
      const S jump = w.len[c] * tr;
      const S compression = 0.5 * (1.0 - jump / smoothAbs(jump, u_width));
      const S q = w.rho_eff[c] * compression * c2 * jump * jump;
      const S& eta = L.shear_viscosity;
      const S lambda = L.viscosity - eta;
      const S area = v.op.dx() * w.len[c];
      const S normal = L.p + q - lambda * tr, deviatoric = -eta * dev;
      w.heat[c] += area * (-(L.p_kinetic + q) * tr + eta * dev * dev + lambda * tr * tr);
      cellStrainForces(v, w, i, k, S(area * (normal + deviatoric)),
                       S(area * (normal - deviatoric)));
    }
}

// The shear strain at the corner of face column i (between columns i and i + 1) and interface
// j (0 < j < N): du/dz across the interface plus dw/dx along z (the derivative along the layer
// less the interface's slope times dw/dz). None at the plate, the free surface or a side wall
// (smooth walls and a free surface carry no shear stress).
template <class S>
void cornerStress(const StateView<S>& v, GranularHydro2D::Workspace<S>& w, int i, int j) {
  const ColumnGrid& g = w.grid;
  const double dx = v.op.dx(), floor = v.op.cellRegularisation().length_floor;
  const int r = g.right(i);
  const int c0 = g.cell(i, j - 1), c1 = g.cell(i, j), r0 = g.cell(r, j - 1), r1 = g.cell(r, j);
  const S dzf = smoothPositivePart(S(0.5 * (w.zc[c1] + w.zc[r1] - w.zc[c0] - w.zc[r0])), floor);
  const S dzi = smoothPositivePart(S(v.z(i, j + 1) - v.z(i, j - 1)), floor);
  const S dzr = smoothPositivePart(S(v.z(r, j + 1) - v.z(r, j - 1)), floor);
  const S sx = (v.z(r, j) - v.z(i, j)) / dx;
  const S wz =
      0.5 * ((v.w(i, j + 1) - v.w(i, j - 1)) / dzi + (v.w(r, j + 1) - v.w(r, j - 1)) / dzr);
  const S gamma = (v.u(i, j) - v.u(i, j - 1)) / dzf + (v.w(r, j) - v.w(i, j)) / dx - sx * wz;
  const S eta = 0.25 * (w.local[c0].shear_viscosity + w.local[c1].shear_viscosity +
                        w.local[r0].shear_viscosity + w.local[r1].shear_viscosity);
  const S area = dx * dzf;
  const S tau = area * eta * gamma;  // the force is -tau d(gamma)/dv
  const S heat = 0.25 * tau * gamma;
  for (int c : {c0, c1, r0, r1}) w.heat[c] += heat;
  w.fu[c1] -= tau / dzf;
  w.fu[c0] += tau / dzf;
  w.fw[g.node(r, j)] -= tau / dx;
  w.fw[g.node(i, j)] += tau / dx;
  const S mi = 0.5 * tau * sx / dzi, mr = 0.5 * tau * sx / dzr;
  w.fw[g.node(i, j + 1)] += mi;
  w.fw[g.node(i, j - 1)] -= mi;
  w.fw[g.node(r, j + 1)] += mr;
  w.fw[g.node(r, j - 1)] -= mr;
}

template <class S>
void cornerStresses(const StateView<S>& v, GranularHydro2D::Workspace<S>& w) {
  for (int i = 0; i < w.grid.Nx; ++i) {
    if (v.op.wallFace(i)) continue;
    for (int j = 1; j < w.grid.N; ++j) cornerStress(v, w, i, j);
  }
}

// The plate and the lid on each column (as GranularHydro1D's boundary nodes, per unit width
// times dx), and the side walls' collisional loss (the contact theorem's flux
// Phi_W^wall p_k sqrt(theta/(2 pi)) through the wall-adjacent cells' height).
template <class S>
void wallContacts(const StateView<S>& v, GranularHydro2D::Workspace<S>& w) {
  const GranularHydro2D& op = v.op;
  const ColumnGrid& g = w.grid;
  const CellRegularisation& reg = op.cellRegularisation();
  const double dx = op.dx(), sigma = op.model().sigma, H = op.geometry().height;
  const int N = g.N;
  for (int i = 0; i < g.Nx; ++i) {
    const int b = g.cell(i, 0), t = g.cell(i, N - 1);
    const WallExchange<S> plate =
        wallExchange(v.z(i, 0), S(-v.w(i, 0)), w.local[b], w.rho_eff[b], sigma, reg.contact_scale,
                     reg.u_width, S(0.5 * w.mass[b]), op.regularisation());
    const WallExchange<S> lid =
        wallExchange(S(H - v.z(i, N)), v.w(i, N), w.local[t], w.rho_eff[t], sigma,
                     reg.contact_scale, reg.u_width, S(0.5 * w.mass[t]), op.regularisation());
    w.fw[g.node(i, 0)] += dx * plate.stress;
    w.fw[g.node(i, N)] -= dx * lid.stress;
    w.heat[b] += dx * (plate.heating - plate.loss);
    w.heat[t] += dx * (lid.heating - lid.loss);
    w.walls[i] = {plate.stress, lid.stress, plate.loss, lid.loss, plate.elastic, lid.elastic};
  }
  w.side_loss = zeroLike(v);
  if (op.periodic()) return;
  for (int i : {0, g.Nx - 1}) {  // a single column meets both walls
    for (int k = 0; k < N; ++k) {
      const int c = g.cell(i, k);
      const S loss = w.local[c].wall_loss * w.local[c].p_kinetic * w.len[c];
      w.heat[c] -= loss;
      w.side_loss += loss;
    }
  }
}

}  // namespace granwave::hydro::layer2d
