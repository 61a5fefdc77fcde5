#include "studies/effective_restitution/CoolingFit.hpp"

#include <cmath>
#include <numbers>

#include "coarse_grain/LineFit.hpp"
#include "hydro/PairCorrelation.hpp"

namespace granwave {

CoolingFit fitCooling(const std::vector<double>& t, const std::vector<double>& theta, double nu,
                      double n, double sigma, double lo, double hi) {
  std::vector<double> x, y;
  double log_sum = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!(theta[i] >= lo && theta[i] <= hi)) continue;
    x.push_back(t[i]);
    y.push_back(1.0 / std::sqrt(theta[i]));
    log_sum += std::log(theta[i]);
  }
  CoolingFit r;
  r.theta_low = lo;
  r.theta_high = hi;
  r.samples = static_cast<int>(x.size());
  if (r.samples < 4) return r;
  r.theta = std::exp(log_sum / r.samples);
  const LineFit fit = fitLine(x, y);
  const double k = 0.5 * std::sqrt(std::numbers::pi) * hydro::pairCorrelation(nu) * n * sigma;
  r.phi_w = {fit.slope / k, fit.slope_error / k};
  const double e2 = 1.0 - r.phi_w.value;
  if (e2 > 0) {
    const double e = std::sqrt(e2);
    r.e_eff = {e, r.phi_w.error / (2.0 * e)};
  }
  return r;
}

std::vector<CoolingFit> fitCoolingByTemperature(const std::vector<double>& t,
                                                const std::vector<double>& theta, double nu,
                                                double n, double sigma, double lo, double hi,
                                                int bins) {
  std::vector<CoolingFit> out;
  const double step = std::log(hi / lo) / bins;
  for (int b = 0; b < bins; ++b) {
    const double top = hi * std::exp(-b * step), bottom = hi * std::exp(-(b + 1) * step);
    out.push_back(fitCooling(t, theta, nu, n, sigma, bottom, top));
  }
  return out;
}

}  // namespace granwave
