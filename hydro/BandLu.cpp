#include "hydro/BandLu.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace granwave::hydro {

namespace {

// The bandwidths, known at compile time for the continuum's two layouts (the loops of
// length kl then compile to straight-line vector code) or at run time for any other.
template <int KL, int KU>
struct FixedBand {
  static constexpr bool fixed = true;
  static constexpr int kl = KL, ku = KU;
};
struct AnyBand {
  static constexpr bool fixed = false;
  int kl, ku;
};

// y[i] -= x[i] t for i = 1..count; count = B::kl in the interior of the matrix.
template <class B>
void subtractMultiple(double* __restrict y, const double* __restrict x, double t, int count,
                      const B& band) {
  if (count == band.kl) {
    for (int i = 1; i <= band.kl; ++i) y[i] -= x[i] * t;
  } else {
    for (int i = 1; i <= count; ++i) y[i] -= x[i] * t;
  }
}

template <class B>
int factor(double* ab, int ldab, int n, const B& band, int* pivots) {
  const int kl = band.kl, ku = band.ku, kv = kl + ku;  // kv: row of the diagonal in a column
  // The fill-in rows start as zeros (the entries of U above A's upper band).
  for (int j = 0; j < n; ++j) std::fill_n(ab + static_cast<long>(j) * ldab, kl, 0.0);
  // (i, j) lives at ab[j ldab + kv + i - j]: pointer to row r of column c.
  const auto at = [&](int row, int col) {
    return ab + static_cast<long>(col) * ldab + kv + row - col;
  };
  int info = 0, ju = 0;  // ju: the last column the interchanges so far have reached
  for (int j = 0; j < n; ++j) {
    const int km = std::min(kl, n - 1 - j);
    double* col = at(j, j);  // col[i] = A(j + i, j)
    int jp = 0;
    double largest = std::abs(col[0]);
    for (int i = 1; i <= km; ++i)
      if (std::abs(col[i]) > largest) {
        largest = std::abs(col[i]);
        jp = i;
      }
    pivots[j] = j + jp;
    if (col[jp] == 0.0) {
      if (info == 0) info = j + 1;
      continue;
    }
    ju = std::max(ju, std::min(j + ku + jp, n - 1));
    if (jp != 0)
      for (int c = j; c <= ju; ++c) std::swap(*at(j + jp, c), *at(j, c));
    if (km == 0) continue;
    const double inverse = 1.0 / col[0];
    for (int i = 1; i <= km; ++i) col[i] *= inverse;
    for (int c = j + 1; c <= ju; ++c) {
      double* target = at(j, c);  // target[i] = A(j + i, c)
      if (target[0] != 0.0) subtractMultiple(target, col, target[0], km, band);
    }
  }
  return info;
}

template <class B>
void solve(const double* ab, int ldab, int n, const B& band, const int* pivots, double* b) {
  const int kl = band.kl, kv = band.kl + band.ku;
  // L: the interchanges and the multipliers, column by column.
  for (int j = 0; j + 1 < n && kl > 0; ++j) {
    if (pivots[j] != j) std::swap(b[j], b[pivots[j]]);
    const double* col = ab + static_cast<long>(j) * ldab + kv;  // col[i] = L(j + i, j)
    subtractMultiple(b + j, col, b[j], std::min(kl, n - 1 - j), band);
  }
  // U (upper band of width kl + ku after the interchanges), backwards.
  for (int j = n - 1; j >= 0; --j) {
    const double* col = ab + static_cast<long>(j) * ldab + kv;  // col[i - j] = U(i, j)
    b[j] /= col[0];
    const double t = b[j];
    if (j >= kv) {
      // b[j - kv + i] -= U(j - kv + i, j) t, i = 0..kv-1: a fixed-length loop for FixedBand.
      double* __restrict y = b + j - kv - 1;
      const double* __restrict x = col - kv - 1;
      if constexpr (B::fixed) {
        for (int i = 1; i <= B::kl + B::ku; ++i) y[i] -= x[i] * t;
      } else {
        for (int i = 1; i <= kv; ++i) y[i] -= x[i] * t;
      }
    } else {
      for (int i = 0; i < j; ++i) b[i] -= col[i - j] * t;
    }
  }
}

}  // namespace

int bandLuFactor(double* ab, int ldab, int n, int kl, int ku, int* pivots) {
  if (kl == 8 && ku == 8) return factor(ab, ldab, n, FixedBand<8, 8>{}, pivots);
  if (kl == 11 && ku == 11) return factor(ab, ldab, n, FixedBand<11, 11>{}, pivots);
  return factor(ab, ldab, n, AnyBand{kl, ku}, pivots);
}

void bandLuSolve(const double* ab, int ldab, int n, int kl, int ku, const int* pivots, double* b) {
  if (kl == 8 && ku == 8) return solve(ab, ldab, n, FixedBand<8, 8>{}, pivots, b);
  if (kl == 11 && ku == 11) return solve(ab, ldab, n, FixedBand<11, 11>{}, pivots, b);
  solve(ab, ldab, n, AnyBand{kl, ku}, pivots, b);
}

}  // namespace granwave::hydro
