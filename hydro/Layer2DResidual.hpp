#pragma once
// GranularHydro2D's right-hand side from its parts (Layer2DState, Layer2DStress,
// Layer2DTransport), on any scalar type. Internal to the 2D operator.
#include <cmath>

#include "hydro/Layer2DStress.hpp"
#include "hydro/Layer2DTransport.hpp"

namespace granwave::hydro {

namespace layer2d {

// dU/dt from the forces and powers the parts accumulated.
template <class S>
void assemble(double t, const StateView<S>& v, const GranularHydro2D::Workspace<S>& w, S* dU) {
  using std::exp;
  const GranularHydro2D& op = v.op;
  const ColumnGrid& g = w.grid;
  const double dx = op.dx(), geff = op.effectiveGravity(t), unit = op.thetaUnit();
  for (int i = 0; i < g.Nx; ++i) {
    const int r = g.right(i);
    for (int j = 0; j <= g.N; ++j) {
      const int n = g.node(i, j);
      const S below = j > 0 ? w.mass[g.cell(i, j - 1)] : zeroLike(v);
      const S above = j < g.N ? w.mass[g.cell(i, j)] : zeroLike(v);
      dU[op.heightIndex(i, j)] = v.w(i, j) - w.drift[n];
      dU[op.velocityIndex(i, j)] = w.fw[n] / (0.5 * dx * (below + above)) - geff;
    }
    for (int k = 0; k < g.N; ++k) {
      const int c = g.cell(i, k);
      const S mass = dx * w.mass[c];
      dU[op.temperatureIndex(i, k)] = w.heat[c] / (mass * unit * exp(v.s(i, k)));
      const bool wall = op.wallFace(i);
      dU[op.fluxIndex(i, k)] = wall ? zeroLike(v) : w.flux[c];
      dU[op.horizontalVelocityIndex(i, k)] =
          wall ? zeroLike(v) : S(w.fu[c] / (0.5 * dx * (w.mass[c] + w.mass[g.cell(r, k)])));
      if (!op.rough()) continue;
      const S theta = unit * exp(v.s(i, k)), spin = unit * exp(v.sr(i, k));
      dU[op.temperatureIndex(i, k)] += w.exchange[c] / theta;
      dU[op.rotationIndex(i, k)] = w.spin[c] / spin + w.heat_r[c] / (mass * spin);
    }
  }
}

}  // namespace layer2d

template <class S>
int GranularHydro2D::residual(double t, const S* U, S* dU, Workspace<S>& w) const {
  for (int k = 0; k < layerSize(); ++k)
    if (!std::isfinite(value(U[k]))) return 1;
  for (int k = layerSize(); k < size(); ++k) dU[k] = constantLike(U[0], 0.0);  // quadratures
  const layer2d::StateView<S> v{*this, U};
  for (S& f : w.fu) f = constantLike(U[0], 0.0);
  for (S& f : w.fw) f = constantLike(U[0], 0.0);
  layer2d::cellStates(v, w);
  layer2d::layerGeometry(v, w);
  layer2d::massFluxes(v, w);
  layer2d::interfaceDrift(w);
  layer2d::cellStresses(v, w);
  layer2d::cornerStresses(v, w);
  layer2d::wallContacts(v, w);
  layer2d::heatConduction(v, w);
  layer2d::temperatureAdvection(v, w);
  layer2d::horizontalMomentumAdvection(v, w);
  layer2d::verticalMomentumAdvection(v, w);
  for (int c = 0; c < static_cast<int>(w.heat.size()); ++c)
    w.heat[c] -= w.local[c].cooling * (dx() * w.len[c]);
  layer2d::assemble(t, v, w, dU);
  for (int k = 0; k < layerSize(); ++k)
    if (!std::isfinite(value(dU[k]))) return 1;
  return 0;
}

}  // namespace granwave::hydro
