#pragma once
// A measured value with its one-sigma uncertainty, how several are combined, and how the
// report prints them.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace granwave {

struct Measurement {
  double value = std::numeric_limits<double>::quiet_NaN();
  double error = std::numeric_limits<double>::quiet_NaN();
  bool valid() const { return std::isfinite(value); }
};

// Inverse-variance weighted mean of the valid entries. When they scatter more than their
// errors allow (chi^2 / (n - 1) > 1) the error is scaled by sqrt(chi^2 / (n - 1)) (the
// Particle Data Group's scale factor), so seed-to-seed scatter is never hidden. Entries
// without an error count with the mean of the others' errors; none valid: invalid result.
Measurement combine(const std::vector<Measurement>& values);

// Mean and standard error of the mean of the finite values (error NaN for fewer than 2).
Measurement meanAndStandardError(const std::vector<double>& values);

// (a - b) / sqrt(sa^2 + sb^2): how many combined sigmas two measurements differ by.
double sigmaDistance(const Measurement& a, const Measurement& b);

// "1.64 ± 0.45" with `digits` decimals, or more (up to 5) so that the error keeps two
// significant digits (an error below 1e-4 in a power of ten: "(1.2 ± 0.3)e-7"); `unit`, if
// given, after the number. A value whose error is as large as itself is not measured: it
// prints as its one-sigma bound, "< 2.1 (not resolved: error ≥ value)" (|value| + error;
// "> -2.1" for a negative value); a zero error, "0.92 (error 0: no spread)". "–" when invalid:
// formatOr gives the reason instead.
std::string format(const Measurement& m, int digits = 2, const std::string& unit = "");
// format(m, digits, unit), or `absent` (why there is no value) when m is invalid.
std::string formatOr(const Measurement& m, const std::string& absent, int digits = 2,
                     const std::string& unit = "");
std::string formatNumber(double v, int digits = 2);
// The shortest form of a number ("{:g}": 2.5, 1e-05), for run labels and scene overrides.
std::string formatCompact(double v);

}  // namespace granwave
