#pragma once
// The scalar types the continuum model is evaluated in: `double` for the right-hand side, and
// Eigen's forward-mode automatic-differentiation scalar (Jet<N>, N directional derivatives)
// for its exact Jacobian (docs/hydro.md, "Jacobian"). Every closure and the discrete operator
// are templates on the scalar, so the Jacobian is the derivative of exactly the function
// CVODE integrates, not a finite-difference estimate of it.
//
// Functions whose derivative is known in closed form but that Eigen's AutoDiff does not
// provide (erfc inside the wet restitution closure, powers with a fractional exponent inside
// the dry one) go through `chain`: value and derivative evaluated in double, combined here.
#include <Eigen/Core>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

namespace granwave::hydro {

template <int N>
using Jet = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;

inline double value(double x) { return x; }
template <int N>
double value(const Jet<N>& x) {
  return x.value();
}

// f(x) given f = f(value(x)) and df = f'(value(x)).
inline double chain(double, double f, double) { return f; }
template <int N>
Jet<N> chain(const Jet<N>& x, double f, double df) {
  return Jet<N>(f, df * x.derivatives());
}

// A scalar of the same type as `like` holding a constant.
inline double constantLike(double, double c) { return c; }
template <int N>
Jet<N> constantLike(const Jet<N>&, double c) {
  return Jet<N>(c, Eigen::Matrix<double, N, 1>::Zero());
}

// max(x, 0) smoothed over `width` > 0: 0.5 (x + sqrt(x^2 + width^2)). C-infinity, so Newton's
// method sees a differentiable right-hand side.
template <class S>
S smoothPositivePart(const S& x, double width) {
  using std::sqrt;
  return 0.5 * (x + sqrt(x * x + width * width));
}

// max(a, b) smoothed over `width`.
template <class S>
S smoothMax(const S& a, const S& b, double width) {
  return b + smoothPositivePart(S(a - b), width);
}

// max(x, floor) blended over [floor - width, floor + width] by a quadratic: exactly x above,
// exactly floor below, continuous slope (C1) between. For floors that must not touch values
// in the valid range.
template <class S>
S blendedMax(const S& x, double floor, double width) {
  if (value(x) >= floor + width) return x;
  if (value(x) <= floor - width) return constantLike(x, floor);
  const S d = x - floor + width;
  return floor + d * d / (4.0 * width);
}

// |x| smoothed over `width`.
template <class S>
S smoothAbs(const S& x, double width) {
  using std::sqrt;
  return sqrt(x * x + width * width);
}

// The limited slope of a cell from its backward difference a and forward difference b: the
// harmonic mean 2ab/(a + b) (van Leer) where a and b have the same sign, zero at an extremum,
// so face values stay within [0, 2] times the cell value for a positive field (the bound the
// semi-discrete positivity argument of docs/hydro.md needs). `width2` (the square of a
// difference scale) smooths the switch at ab = 0.
template <class S>
S limitedSlope(const S& a, const S& b, double width2) {
  const S ab = a * b;
  const S sum = a + b;
  return 2.0 * smoothPositivePart(ab, width2) * sum / (sum * sum + width2);
}

}  // namespace granwave::hydro
