#include "hydro/RestitutionClosure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace granwave::hydro {

namespace {

const double kSqrtPi = std::sqrt(std::numbers::pi);
const double kGamma21_10 = std::tgamma(2.1);                               // 1.04649
const double kGamma11_5 = std::tgamma(2.2);                                // 1.10180
const double kGamma8_5OverGamma3_2 = std::tgamma(1.6) / std::tgamma(1.5);  // 1.00822
const double kFourToTheTenth = std::pow(4.0, 0.1), kTwoToTheTenth = std::pow(2.0, 0.1);
constexpr double kInf = std::numeric_limits<double>::infinity();

void requireInUnitInterval(double value, const char* what) {
  if (!(value >= 0.0 && value <= 1.0)) {
    throw std::invalid_argument(std::string("RestitutionClosure: ") + what + " = " +
                                std::to_string(value) + " is outside [0, 1]");
  }
}

void requireNonNegative(double value, const char* what) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string("RestitutionClosure: ") + what + " = " +
                                std::to_string(value) + " must be finite and >= 0");
  }
}

// --- adaptive Simpson (Lyness), with the Richardson correction --------------------------------

template <class F>
double simpsonStep(const F& f, double a, double b, double fa, double fm, double fb, double whole,
                   double tol, int depth) {
  const double m = 0.5 * (a + b);
  const double lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  const double delta = left + right - whole;
  if (depth <= 0 || std::abs(delta) <= 15.0 * tol) return left + right + delta / 15.0;
  return simpsonStep(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1) +
         simpsonStep(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1);
}

template <class F>
double adaptiveSimpson(const F& f, double a, double b, double tol) {
  const double fa = f(a), fb = f(b), fm = f(0.5 * (a + b));
  const double whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
  return simpsonStep(f, a, b, fa, fm, fb, whole, tol, 40);
}

// int_0^10 f(x) dx on panels of width 0.25 (so the Gaussian bump is never missed), with a
// break at `kink` (the wet onset) when it falls inside. The weights integrate to O(1), so an
// absolute tolerance per panel is a relative one.
template <class F>
double integrateReduced(const F& f, double kink) {
  constexpr double kUpper = 10.0;  // exp(-100): far below double precision of the O(1) result
  std::vector<double> breaks;
  for (int i = 0; i <= 40; ++i) breaks.push_back(0.25 * i);
  if (kink > 0.0 && kink < kUpper) breaks.push_back(kink);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    if (breaks[i + 1] > breaks[i]) sum += adaptiveSimpson(f, breaks[i], breaks[i + 1], 1e-15);
  }
  return sum;
}

// 2 int_0^inf x^3 e^{-x^2} (1 - e(x sqrt(w theta))^2) dx.
double numericalLossAverage(const RestitutionClosure& c, double theta, double w) {
  const double scale = std::sqrt(w * theta);  // u = scale * x
  const auto f = [&](double x) {
    const double e = c.coefficient(scale * x);
    return 2.0 * x * x * x * std::exp(-x * x) * (1.0 - e * e);
  };
  return integrateReduced(f, c.onsetVelocity() / scale);
}

}  // namespace

double RestitutionAverages::effectiveRestitution() const {
  return std::sqrt(std::max(0.0, 1.0 - phi_w));
}

RestitutionClosure RestitutionClosure::constant(double e) {
  requireInUnitInterval(e, "constant restitution e");
  return RestitutionClosure(Law::Constant, e, 0.0, 0.0);
}

RestitutionClosure RestitutionClosure::dry(double kappa) {
  requireNonNegative(kappa, "dry kappa");
  return RestitutionClosure(Law::Dry, 1.0, kappa, 0.0);
}

RestitutionClosure RestitutionClosure::wet(double e_inf, double onset_velocity) {
  requireInUnitInterval(e_inf, "wet e_inf");
  requireNonNegative(onset_velocity, "wet onset velocity v_c");
  return RestitutionClosure(Law::Wet, e_inf, 0.0, onset_velocity);
}

double RestitutionClosure::coefficient(double u) const {
  switch (law_) {
    case Law::Constant:
      return e_;
    case Law::Dry:
      return std::clamp(1.0 - kappa_ * std::pow(u, 0.2), 0.0, 1.0);
    case Law::Wet:
      return u >= v_c_ && u > 0.0 ? e_ * (1.0 - v_c_ / u) : 0.0;
  }
  return e_;
}

double RestitutionClosure::lossAverage(double theta, double w) const {
  switch (law_) {
    case Law::Constant:
      return 1.0 - e_ * e_;
    case Law::Dry: {
      if (theta <= 0.0) return 0.0;
      const double s = std::pow(w * theta, 0.1);
      return 2.0 * kappa_ * kGamma21_10 * s - kappa_ * kappa_ * kGamma11_5 * s * s;
    }
    case Law::Wet: {
      if (theta <= 0.0) return 1.0;
      const double y = v_c_ / std::sqrt(w * theta);
      return 1.0 - e_ * e_ * (std::exp(-y * y) - kSqrtPi * y * std::erfc(y));
    }
  }
  return 0.0;
}

double RestitutionClosure::lossAverageDerivative(double theta, double w) const {
  switch (law_) {
    case Law::Constant:
      return 0.0;
    case Law::Dry: {
      if (kappa_ == 0.0) return 0.0;
      if (theta <= 0.0) return kInf;
      const double s = std::pow(w * theta, 0.1);
      return (0.2 * kappa_ * kGamma21_10 * s - 0.2 * kappa_ * kappa_ * kGamma11_5 * s * s) / theta;
    }
    case Law::Wet: {
      if (theta <= 0.0) return 0.0;
      const double y = v_c_ / std::sqrt(w * theta);
      return -e_ * e_ * kSqrtPi * std::erfc(y) * y / (2.0 * theta);
    }
  }
  return 0.0;
}

double RestitutionClosure::phiW(double theta) const { return lossAverage(theta, 4.0); }
double RestitutionClosure::phiWall(double theta) const { return lossAverage(theta, 2.0); }
double RestitutionClosure::dPhiWdTheta(double theta) const {
  return lossAverageDerivative(theta, 4.0);
}
double RestitutionClosure::dPhiWallDTheta(double theta) const {
  return lossAverageDerivative(theta, 2.0);
}

double RestitutionClosure::phiP(double theta) const {
  switch (law_) {
    case Law::Constant:
      return 1.0 + e_;
    case Law::Dry:
      if (theta <= 0.0) return 2.0;
      return 2.0 - kappa_ * kGamma8_5OverGamma3_2 * std::pow(4.0 * theta, 0.1);
    case Law::Wet: {
      if (theta <= 0.0) return 1.0;
      const double y = v_c_ / std::sqrt(4.0 * theta);
      return 1.0 + e_ * std::erfc(y);
    }
  }
  return 1.0 + e_;
}

double RestitutionClosure::dPhiPdTheta(double theta) const {
  switch (law_) {
    case Law::Constant:
      return 0.0;
    case Law::Dry:
      if (kappa_ == 0.0) return 0.0;
      if (theta <= 0.0) return -kInf;
      return -0.1 * kappa_ * kGamma8_5OverGamma3_2 * std::pow(4.0 * theta, 0.1) / theta;
    case Law::Wet: {
      if (theta <= 0.0) return 0.0;
      const double y = v_c_ / std::sqrt(4.0 * theta);
      return e_ * y * std::exp(-y * y) / (kSqrtPi * theta);
    }
  }
  return 0.0;
}

double RestitutionClosure::d2PhiPdTheta2(double theta) const {
  switch (law_) {
    case Law::Constant:
      return 0.0;
    case Law::Dry:
      if (kappa_ == 0.0) return 0.0;
      if (theta <= 0.0) return kInf;
      return 0.09 * kappa_ * kGamma8_5OverGamma3_2 * std::pow(4.0 * theta, 0.1) / (theta * theta);
    case Law::Wet: {
      if (theta <= 0.0) return 0.0;
      const double y = v_c_ / std::sqrt(4.0 * theta);
      return -e_ * y * std::exp(-y * y) * (1.5 - y * y) / (kSqrtPi * theta * theta);
    }
  }
  return 0.0;
}

MaxwellAverages RestitutionClosure::allAverages(double theta) const {
  MaxwellAverages a;
  switch (law_) {
    case Law::Constant:
      a.phi_w = a.phi_wall = 1.0 - e_ * e_;
      a.phi_p = 1.0 + e_;
      return a;
    case Law::Dry: {
      if (theta <= 0.0 || kappa_ == 0.0) {
        a.phi_w = phiW(theta), a.dphi_w = dPhiWdTheta(theta);
        a.phi_p = phiP(theta), a.dphi_p = dPhiPdTheta(theta), a.d2phi_p = d2PhiPdTheta2(theta);
        a.phi_wall = phiWall(theta), a.dphi_wall = dPhiWallDTheta(theta);
        return a;
      }
      const double s = std::pow(theta, 0.1);                        // theta^(1/10)
      const auto loss = [&](double p, double& phi, double& dphi) {  // p = (w theta)^(1/10)
        phi = 2.0 * kappa_ * kGamma21_10 * p - kappa_ * kappa_ * kGamma11_5 * p * p;
        dphi =
            (0.2 * kappa_ * kGamma21_10 * p - 0.2 * kappa_ * kappa_ * kGamma11_5 * p * p) / theta;
      };
      loss(kFourToTheTenth * s, a.phi_w, a.dphi_w);
      loss(kTwoToTheTenth * s, a.phi_wall, a.dphi_wall);
      const double c =
          kappa_ * kGamma8_5OverGamma3_2 * kFourToTheTenth * s;  // kappa R (4 theta)^(1/10)
      a.phi_p = 2.0 - c;
      a.dphi_p = -0.1 * c / theta;
      a.d2phi_p = 0.09 * c / (theta * theta);
      return a;
    }
    case Law::Wet: {
      if (theta <= 0.0) {
        a.phi_w = a.phi_wall = 1.0;
        a.phi_p = 1.0;
        return a;
      }
      const double y4 = v_c_ / (2.0 * std::sqrt(theta)), y2 = std::numbers::sqrt2 * y4;
      const double e4 = std::exp(-y4 * y4), erfc4 = std::erfc(y4);
      const double e2 = std::exp(-y2 * y2), erfc2 = std::erfc(y2);
      const double ee = e_ * e_;
      a.phi_w = 1.0 - ee * (e4 - kSqrtPi * y4 * erfc4);
      a.dphi_w = -ee * kSqrtPi * erfc4 * y4 / (2.0 * theta);
      a.phi_wall = 1.0 - ee * (e2 - kSqrtPi * y2 * erfc2);
      a.dphi_wall = -ee * kSqrtPi * erfc2 * y2 / (2.0 * theta);
      a.phi_p = 1.0 + e_ * erfc4;
      a.dphi_p = e_ * y4 * e4 / (kSqrtPi * theta);
      a.d2phi_p = -e_ * y4 * e4 * (1.5 - y4 * y4) / (kSqrtPi * theta * theta);
      return a;
    }
  }
  return a;
}

double RestitutionClosure::effectiveRestitution(double theta) const {
  return std::sqrt(std::max(0.0, 1.0 - phiW(theta)));
}

double numericalPhiW(const RestitutionClosure& closure, double theta) {
  return numericalLossAverage(closure, theta, 4.0);
}

double numericalPhiWall(const RestitutionClosure& closure, double theta) {
  return numericalLossAverage(closure, theta, 2.0);
}

// (4/sqrt(pi)) int_0^inf x^2 e^{-x^2} (1 + e(x sqrt(4 theta))) dx.
double numericalPhiP(const RestitutionClosure& closure, double theta) {
  const double scale = std::sqrt(4.0 * theta);
  const auto f = [&](double x) {
    return 4.0 / kSqrtPi * x * x * std::exp(-x * x) * (1.0 + closure.coefficient(scale * x));
  };
  return integrateReduced(f, closure.onsetVelocity() / scale);
}

}  // namespace granwave::hydro
