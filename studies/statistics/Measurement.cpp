#include "studies/statistics/Measurement.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace granwave {

Measurement combine(const std::vector<Measurement>& values) {
  double mean_error = 0;
  int with_error = 0, n = 0;
  for (const Measurement& m : values) {
    if (!m.valid()) continue;
    ++n;
    if (std::isfinite(m.error) && m.error > 0) {
      mean_error += m.error;
      ++with_error;
    }
  }
  if (n == 0) return {};
  const double fallback = with_error ? mean_error / with_error : 0.0;
  if (fallback == 0.0) {  // no errors at all: plain mean and standard error
    double s = 0, s2 = 0;
    for (const Measurement& m : values)
      if (m.valid()) s += m.value;
    const double mean = s / n;
    for (const Measurement& m : values)
      if (m.valid()) s2 += (m.value - mean) * (m.value - mean);
    return {mean, n > 1 ? std::sqrt(s2 / (n - 1) / n) : std::numeric_limits<double>::quiet_NaN()};
  }
  double sw = 0, swx = 0;
  auto sigma = [&](const Measurement& m) {
    return std::isfinite(m.error) && m.error > 0 ? m.error : fallback;
  };
  for (const Measurement& m : values) {
    if (!m.valid()) continue;
    const double w = 1.0 / (sigma(m) * sigma(m));
    sw += w;
    swx += w * m.value;
  }
  const double mean = swx / sw;
  double chi2 = 0;
  for (const Measurement& m : values)
    if (m.valid()) chi2 += std::pow((m.value - mean) / sigma(m), 2);
  double error = std::sqrt(1.0 / sw);
  if (n > 1 && chi2 / (n - 1) > 1.0) error *= std::sqrt(chi2 / (n - 1));
  return {mean, error};
}

Measurement meanAndStandardError(const std::vector<double>& values) {
  std::vector<Measurement> m;
  for (double x : values)
    if (std::isfinite(x)) m.push_back({x, std::numeric_limits<double>::quiet_NaN()});
  return combine(m);
}

double sigmaDistance(const Measurement& a, const Measurement& b) {
  const double ea = std::isfinite(a.error) ? a.error : 0.0;
  const double eb = std::isfinite(b.error) ? b.error : 0.0;
  const double s = std::sqrt(ea * ea + eb * eb);
  return s > 0 ? (a.value - b.value) / s : std::numeric_limits<double>::quiet_NaN();
}

std::string formatNumber(double v, int digits) {
  if (!std::isfinite(v)) return "–";
  return fmt::format("{:.{}f}", v, digits);
}

std::string formatCompact(double v) { return fmt::format("{:g}", v); }

std::string format(const Measurement& m, int digits) {
  if (!m.valid()) return "–";
  if (!std::isfinite(m.error)) return formatNumber(m.value, digits);
  // At least `digits` decimals, more if needed to show two significant digits of the error.
  if (m.error > 0)
    digits = std::clamp(1 - static_cast<int>(std::floor(std::log10(m.error))), digits, 5);
  return fmt::format("{:.{}f} ± {:.{}f}", m.value, digits, m.error, digits);
}

}  // namespace granwave
