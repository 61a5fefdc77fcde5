// The exact Jacobian of GranularHydro2D by forward-mode differentiation of its right-hand side
// (hydro/Scalar.hpp), coloured: within a column, blocks six apart never meet in a row (a row
// of block k reaches blocks k-2..k+3), and columns more than 2 R apart (R = kColumnReach)
// never meet either, so one pass per column colour, with 6 K directional derivatives, gives
// every element.
#include <algorithm>
#include <cmath>
#include <vector>

#include "hydro/GranularHydro2D.hpp"
#include "hydro/Layer2DResidual.hpp"

namespace granwave::hydro {

namespace {

constexpr int kBlockColours = 6;

// Colours of the columns: equal colours are more than 2 R apart, cyclically when periodic
// (the columns past the last whole group of 2 R + 1 get colours of their own).
std::vector<int> columnColours(int Nx, bool periodic, int reach) {
  const int C = 2 * reach + 1;
  std::vector<int> colour(Nx);
  const int whole = periodic ? Nx / C * C : Nx;
  for (int i = 0; i < Nx; ++i) colour[i] = Nx <= C ? i : (i < whole ? i % C : C + i - whole);
  return colour;
}

// The distinct columns within `reach` of column i.
std::vector<int> columnsNear(int i, int Nx, bool periodic, int reach) {
  std::vector<int> near;
  for (int d = -reach; d <= reach; ++d) {
    int c = i + d;
    if (periodic) c = ((c % Nx) + Nx) % Nx;
    if (c < 0 || c >= Nx) continue;
    bool seen = false;
    for (int e : near) seen = seen || e == c;
    if (!seen) near.push_back(c);
  }
  return near;
}

// Writes the derivatives of one coloured column entry (column `col`, block `b`, colour slot
// `sl`) into the rows of the blocks b-3..b+2 of every column at `row_offsets`: the reach of
// the operator's stencil (a row of block k depends on blocks k-2..k+3: u_k through the
// drift of node k+2, whose mass fluxes see the density of layer k+2, bounded by z_k+3). False
// on a derivative that is not finite.
template <class Jets, class Writer>
bool scatterColumnEntry(const Jets& dU, const std::vector<int>& row_offsets, int b, int N, int K,
                        int sl, int col, const Writer& write) {
  for (int offset : row_offsets)
    for (int rb = std::max(0, b - 3); rb <= std::min(N, b + 2); ++rb)
      for (int e = 0; e < (rb == N ? 2 : K); ++e) {
        const int row = offset + rb * K + e;
        const double d = dU[row].derivatives()[sl];
        if (!std::isfinite(d)) return false;
        if (d != 0) write(row, col, d);
      }
  return true;
}

}  // namespace

template <int Colours>
int GranularHydro2D::jacobianWith(double t, const double* U, const SparseWriter& write,
                                  bool in_column_only, JetWorkspace<Colours>& j) const {
  using J = Jet<Colours>;
  const int K = vars_, Nx = x_.columns, N = g_.cells, n_col = columnSize();
  const std::vector<int> colour = columnColours(Nx, x_.periodic, kColumnReach);
  const int passes = *std::max_element(colour.begin(), colour.end()) + 1;
  auto slot = [&](int m) { return (m / K) % kBlockColours * K + m % K; };
  for (int pass = 0; pass < passes; ++pass) {
    for (int k = 0; k < size(); ++k) j.U[k] = J(U[k], Eigen::Matrix<double, Colours, 1>::Zero());
    for (int i = 0; i < Nx; ++i)
      if (colour[i] == pass)
        for (int m = 0; m < n_col; ++m)
          j.U[columnOffset(i) + m] = J(U[columnOffset(i) + m], Colours, slot(m));
    if (residual(t, j.U.data(), j.dU.data(), j.w) != 0) return 1;
    for (int i = 0; i < Nx; ++i) {
      if (colour[i] != pass) continue;
      std::vector<int> offsets;
      for (int r :
           in_column_only ? std::vector<int>{i} : columnsNear(i, Nx, x_.periodic, kColumnReach))
        offsets.push_back(columnOffset(r));
      for (int m = 0; m < n_col; ++m)
        if (!scatterColumnEntry(j.dU, offsets, m / K, N, K, slot(m), columnOffset(i) + m, write))
          return 1;
    }
  }
  return 0;
}

int GranularHydro2D::jacobian(double t, const double* U, const SparseWriter& write,
                              bool in_column_only) const {
  if (rough()) {
    if (!rough_jets_)
      rough_jets_ = std::make_unique<JetWorkspace<36>>(x_.columns, g_.cells, x_.periodic, size());
    return jacobianWith(t, U, write, in_column_only, *rough_jets_);
  }
  if (!smooth_jets_)
    smooth_jets_ = std::make_unique<JetWorkspace<30>>(x_.columns, g_.cells, x_.periodic, size());
  return jacobianWith(t, U, write, in_column_only, *smooth_jets_);
}

}  // namespace granwave::hydro
