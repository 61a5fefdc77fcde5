#include "hydro/ColumnPreconditioner.hpp"

#include <algorithm>
#include <cstdlib>

#include "hydro/BandLu.hpp"

namespace granwave::hydro {

ColumnPreconditioner::ColumnPreconditioner(const GranularHydro2D& op)
    : op_(op),
      n_(op.columnSize()),
      band_(op.halfBand()),
      band_w_(2 * op.halfBand() + 1),
      jac_(static_cast<std::size_t>(op.columns()) * n_ * band_w_, 0.0),
      lu_(static_cast<std::size_t>(op.columns()) * n_ * (3 * op.halfBand() + 1), 0.0),
      pivots_(static_cast<std::size_t>(op.columns()) * n_, 0) {}

int ColumnPreconditioner::setup(double t, const double* y, bool jacobian_ok, double gamma,
                                bool& recomputed) {
  recomputed = !jacobian_ok;
  if (!jacobian_ok) {
    std::fill(jac_.begin(), jac_.end(), 0.0);
    const int status = op_.jacobian(
        t, y,
        [this](int row, int col, double v) {
          const int column = row / n_, r = row % n_, c = col % n_;
          jacobianAt(column)[static_cast<long>(c) * band_w_ + r - c + band_] = v;
        },
        true);
    if (status != 0) return 1;
    ++jacobians_;
  }
  const int kl = band_, ld = ldab();
  for (int column = 0; column < op_.columns(); ++column) {
    const double* J = jacobianAt(column);
    double* ab = lu_.data() + static_cast<long>(column) * n_ * ld;
    // (i, j) at ab[j ld + 2 kl + i - j]; rows 0..kl-1 of each column are the LU's fill-in.
    for (int j = 0; j < n_; ++j)
      for (int i = std::max(0, j - band_); i <= std::min(n_ - 1, j + band_); ++i)
        ab[static_cast<long>(j) * ld + 2 * kl + i - j] =
            (i == j ? 1.0 : 0.0) - gamma * J[static_cast<long>(j) * band_w_ + i - j + band_];
    if (bandLuFactor(ab, ld, n_, kl, kl, pivots_.data() + static_cast<long>(column) * n_) != 0)
      return 1;  // singular: CVODE retries with a smaller step
  }
  return 0;
}

int ColumnPreconditioner::solve(const double* r, double* z) const {
  std::copy(r, r + op_.size(), z);  // the energy-budget quadratures: P = I
  for (int column = 0; column < op_.columns(); ++column)
    bandLuSolve(lu_.data() + static_cast<long>(column) * n_ * ldab(), ldab(), n_, band_, band_,
                pivots_.data() + static_cast<long>(column) * n_, z + op_.columnOffset(column));
  return 0;
}

KrylovPreconditioner ColumnPreconditioner::callbacks() {
  return {[this](double t, const double* y, bool ok, double gamma, bool& recomputed) {
            return setup(t, y, ok, gamma, recomputed);
          },
          [this](const double* r, double* z) { return solve(r, z); }};
}

}  // namespace granwave::hydro
