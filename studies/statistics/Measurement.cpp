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

namespace {

// A positive number to two significant digits: 2.1, 0.031, 120, 4.6e-7.
std::string twoSignificant(double x) {
  const int exponent = static_cast<int>(std::floor(std::log10(x)));
  if (exponent >= -4 && exponent < 5) return fmt::format("{:.{}f}", x, std::max(0, 1 - exponent));
  return fmt::format("{:.1f}e{}", x / std::pow(10.0, exponent), exponent);
}

}  // namespace

std::string format(const Measurement& m, int digits, const std::string& unit) {
  if (!m.valid()) return "–";
  const std::string u = unit.empty() ? "" : " " + unit;
  if (!std::isfinite(m.error)) return formatNumber(m.value, digits) + u;
  // A zero error is no spread among the values combined (seeds that agree exactly), not a
  // measurement without uncertainty: "0.00 ± 0.00" would claim one.
  if (m.error == 0) return formatNumber(m.value, digits) + u + " (error 0: no spread)";
  // Its error as large as the value: the sign and size are not measured, only a bound.
  if (m.error > 0 && m.error >= std::abs(m.value)) {
    const std::string bound = twoSignificant(std::abs(m.value) + m.error);
    return fmt::format("{}{}{} (not resolved: error ≥ value)", m.value < 0 ? "> -" : "< ", bound,
                       u);
  }
  // At least `digits` decimals, more if needed to show two significant digits of the error;
  // an error below 1e-4 in a power of ten, so that no small number prints as 0.00000.
  if (m.error > 0 && m.error < 1e-4) {
    const int exponent =
        static_cast<int>(std::floor(std::log10(std::max(std::abs(m.value), m.error))));
    const double scale = std::pow(10.0, exponent);
    const int decimals =
        std::max(1, exponent + 1 - static_cast<int>(std::floor(std::log10(m.error))));
    return fmt::format("({:.{}f} ± {:.{}f})e{}{}", m.value / scale, decimals, m.error / scale,
                       decimals, exponent, u);
  }
  if (m.error > 0)
    digits = std::clamp(1 - static_cast<int>(std::floor(std::log10(m.error))), digits, 5);
  return fmt::format("{:.{}f} ± {:.{}f}{}", m.value, digits, m.error, digits, u);
}

std::string formatOr(const Measurement& m, const std::string& absent, int digits,
                     const std::string& unit) {
  return m.valid() ? format(m, digits, unit) : absent;
}

}  // namespace granwave
