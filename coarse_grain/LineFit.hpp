#pragma once
// Ordinary least-squares straight line y = a + b x with the standard error of the slope,
// s_b = sqrt(sum r^2 / (n - 2) / sum (x - x_mean)^2).
#include <cmath>
#include <limits>
#include <vector>

namespace granwave {

struct LineFit {
  double intercept = std::numeric_limits<double>::quiet_NaN();
  double slope = std::numeric_limits<double>::quiet_NaN();
  double slope_error = std::numeric_limits<double>::quiet_NaN();
  int points = 0;
};

inline LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y) {
  LineFit f;
  const int n = static_cast<int>(x.size());
  f.points = n;
  if (n < 2) return f;
  double mx = 0, my = 0;
  for (int k = 0; k < n; ++k) {
    mx += x[k] / n;
    my += y[k] / n;
  }
  double sxx = 0, sxy = 0;
  for (int k = 0; k < n; ++k) {
    sxx += (x[k] - mx) * (x[k] - mx);
    sxy += (x[k] - mx) * (y[k] - my);
  }
  if (sxx <= 0) return f;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  if (n > 2) {
    double rr = 0;
    for (int k = 0; k < n; ++k) {
      const double r = y[k] - f.intercept - f.slope * x[k];
      rr += r * r;
    }
    f.slope_error = std::sqrt(rr / (n - 2) / sxx);
  }
  return f;
}

}  // namespace granwave
