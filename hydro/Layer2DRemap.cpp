#include "hydro/Layer2DRemap.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace granwave::hydro {

namespace {

using Vec = std::vector<double>;

// The means over [b_k, b_k+1] of the piecewise-constant field v on the intervals [a_k, a_k+1]
// (both partitions increasing, of the same range): sum of overlaps times v over the length.
// An empty new interval takes the value of the old interval it sits in.
Vec intervalMeans(const Vec& a, const Vec& v, const Vec& b) {
  Vec out(b.size() - 1, 0.0);
  std::size_t m = 0;
  for (std::size_t k = 0; k + 1 < b.size(); ++k) {
    const double lo = b[k], hi = b[k + 1];
    while (m + 2 < a.size() && a[m + 1] <= lo) ++m;
    double sum = 0;
    for (std::size_t j = m; j + 1 < a.size() && a[j] < hi; ++j)
      sum += std::max(0.0, std::min(hi, a[j + 1]) - std::max(lo, a[j])) * v[j];
    out[k] = hi > lo ? sum / (hi - lo) : v[m];
  }
  return out;
}

// y at x of the piecewise-linear interpolant through (a_j, y_j), a increasing (repeated
// abscissae: the first of them); x outside [a_0, a_n] takes the end value.
double interpolate(const Vec& a, const Vec& y, double x) {
  if (x <= a.front()) return y.front();
  if (x >= a.back()) return y.back();
  const std::size_t j =
      static_cast<std::size_t>(std::upper_bound(a.begin(), a.end(), x) - a.begin());
  const double span = a[j] - a[j - 1];
  return span > 0 ? y[j - 1] + (x - a[j - 1]) / span * (y[j] - y[j - 1]) : y[j];
}

// The cumulative edges of the masses (negative masses, from round-off, count as empty).
Vec cumulative(const Vec& mass) {
  Vec edges(mass.size() + 1, 0.0);
  for (std::size_t k = 0; k < mass.size(); ++k) edges[k + 1] = edges[k] + std::max(mass[k], 0.0);
  return edges;
}

struct LayerMasses {
  std::vector<Vec> cell;  // [i][k], kg/m
  Vec column;             // M_i
  Vec layer;              // L_k
  double total = 0;       // M
};

LayerMasses layerMasses(const GranularHydro2D& op, const double* U) {
  const int Nx = op.columns(), N = op.cells();
  LayerMasses m{std::vector<Vec>(Nx, Vec(N)), Vec(Nx, 0.0), Vec(N, 0.0), 0.0};
  for (int i = 0; i < Nx; ++i)
    for (int k = 0; k < N; ++k) {
      const double mu = op.cellMass(U, i, k);
      m.cell[i][k] = mu;
      m.column[i] += mu;
      m.layer[k] += mu;
      m.total += mu;
    }
  return m;
}

// The mass fluxes that make mu0 + (Phi_i-1,k - Phi_ik)/dx the target masses, keeping each
// layer's mean Phi (periodic) or Phi = 0 left of the first column (side walls).
void setFluxes(const GranularHydro2D& op, const std::vector<Vec>& target, std::vector<double>& U) {
  const int Nx = op.columns(), N = op.cells();
  const double dx = op.dx();
  const int faces = op.periodic() ? Nx : Nx - 1;
  for (int k = 0; k < N; ++k) {
    Vec phi(Nx, 0.0);
    double previous = 0, mean_old = 0, mean_new = 0;
    for (int i = 0; i < Nx; ++i) {
      const double mu0 = op.initialCellMass()[static_cast<std::size_t>(i) * N + k];
      phi[i] = previous - dx * (target[i][k] - mu0);
      previous = phi[i];
    }
    for (int i = 0; i < faces; ++i) {
      mean_old += U[op.fluxIndex(i, k)] / faces;
      mean_new += phi[i] / faces;
    }
    const double shift = op.periodic() ? mean_old - mean_new : 0.0;
    for (int i = 0; i < faces; ++i) U[op.fluxIndex(i, k)] = phi[i] + shift;
  }
}

}  // namespace

double thinnestLayerShare(const GranularHydro2D& op, const double* U) {
  const LayerMasses m = layerMasses(op, U);
  double thinnest = INFINITY;
  for (int i = 0; i < op.columns(); ++i)
    for (int k = 0; k < op.cells(); ++k)
      thinnest = std::min(thinnest, m.cell[i][k] * m.total / (m.column[i] * m.layer[k]));
  return thinnest;
}

double remapLayers(const GranularHydro2D& op, double t, std::vector<double>& U) {
  const int Nx = op.columns(), N = op.cells();
  const LayerMasses m = layerMasses(op, U.data());
  const std::vector<double> old = U;
  const Vec shares = cumulative(m.layer);  // of the whole layer, kg/m summed over columns
  std::vector<Vec> edges(Nx), target(Nx, Vec(N));
  for (int i = 0; i < Nx; ++i) {
    if (!(m.column[i] > 0))
      throw std::runtime_error("remap: column " + std::to_string(i) + " has no mass");
    edges[i] = cumulative(m.cell[i]);
    Vec new_edges(N + 1), z(N + 1), w(N + 1), theta(N), spin(N);
    for (int j = 0; j <= N; ++j) {
      new_edges[j] = edges[i].back() * shares[j] / shares.back();
      z[j] = old[op.heightIndex(i, j)];
      w[j] = old[op.velocityIndex(i, j)];
    }
    for (int k = 0; k < N; ++k) {
      target[i][k] = m.column[i] * m.layer[k] / m.total;
      theta[k] = op.temperatureOf(old[op.temperatureIndex(i, k)]);
      if (op.rough()) spin[k] = op.temperatureOf(old[op.rotationIndex(i, k)]);
    }
    const Vec theta_new = intervalMeans(edges[i], theta, new_edges);
    const Vec spin_new = op.rough() ? intervalMeans(edges[i], spin, new_edges) : Vec();
    for (int j = 1; j < N; ++j) {
      U[op.heightIndex(i, j)] = interpolate(edges[i], z, new_edges[j]);
      U[op.velocityIndex(i, j)] = interpolate(edges[i], w, new_edges[j]);
    }
    for (int k = 0; k < N; ++k) {
      U[op.temperatureIndex(i, k)] = op.temperatureUnknown(theta_new[k]);
      if (op.rough()) U[op.rotationIndex(i, k)] = op.temperatureUnknown(spin_new[k]);
    }
  }
  for (int i = 0; i < Nx; ++i) {  // the faces' horizontal velocities, in the layer-mass fraction
    if (op.wallFace(i)) continue;
    const int r = (i + 1) % Nx;
    Vec a(N + 1), b(N + 1), u(N);
    for (int j = 0; j <= N; ++j) {
      a[j] = 0.5 * (edges[i][j] / edges[i].back() + edges[r][j] / edges[r].back());
      b[j] = shares[j] / shares.back();
    }
    for (int k = 0; k < N; ++k) u[k] = old[op.horizontalVelocityIndex(i, k)];
    const Vec u_new = intervalMeans(a, u, b);
    for (int k = 0; k < N; ++k) U[op.horizontalVelocityIndex(i, k)] = u_new[k];
  }
  setFluxes(op, target, U);
  // The energy the averaging moved, given to the internal energy in proportion to it.
  const double moved = op.labEnergy(t, old.data()) - op.labEnergy(t, U.data());
  double internal = 0;
  for (int i = 0; i < Nx; ++i)
    for (int k = 0; k < N; ++k)
      internal += op.dx() * op.cellView(U.data(), i, k).mass *
                  op.temperatureOf(U[op.temperatureIndex(i, k)]);
  if (!(std::abs(moved) < 0.5 * internal))
    throw std::runtime_error("remap: the energy to move (" + std::to_string(moved) +
                             " J/m) exceeds half the internal energy");
  const double factor = std::log1p(moved / internal);
  for (int i = 0; i < Nx; ++i)
    for (int k = 0; k < N; ++k) U[op.temperatureIndex(i, k)] += factor;
  return moved;
}

}  // namespace granwave::hydro
