#include "coarse_grain/KinkDetector.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace granwave {

namespace {

struct Run {
  int start = 0, end = 0;  // inclusive, in rotated column order
  int sign = 0;
};

// Period-2 difference D(x) = <(-1)^c (h_c - h_{c+1})>_c.
std::vector<double> periodTwoDifference(const std::vector<SurfaceProfile>& cycles) {
  const int n = cycles.front().columns();
  const int pairs = static_cast<int>(cycles.size()) - 1;
  std::vector<double> D(n, 0.0);
  for (int c = 0; c < pairs; ++c) {
    const double sign = c % 2 == 0 ? 1.0 : -1.0;
    for (int i = 0; i < n; ++i)
      D[i] += sign * (cycles[c].height[i] - cycles[c + 1].height[i]) / pairs;
  }
  return D;
}

// Zero crossing of D between the end of one domain and the start of the next (rotated
// indices e < b), as a rotated position in columns (column centre j at j + 1/2).
double crossingPosition(const std::vector<double>& D, int rot, int e, int b) {
  const int n = static_cast<int>(D.size());
  auto at = [&](int j) { return D[(rot + j) % n]; };
  double first = -1, last = -1;
  for (int j = e; j < b; ++j) {
    const double d0 = at(j), d1 = at(j + 1);
    if ((d0 >= 0) == (d1 >= 0)) continue;
    const double pos = j + 0.5 + d0 / (d0 - d1);
    if (first < 0) first = pos;
    last = pos;
  }
  if (first < 0) return 0.5 * (e + b) + 0.5;  // no crossing (cannot happen across a sign change)
  return 0.5 * (first + last);
}

// F = 1 - std/mean of the values v >= median(v) / 2 (the plateau without the transition).
double plateauFlatness(const std::vector<double>& v) {
  std::vector<double> sorted = v;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double half_level = 0.5 * sorted[sorted.size() / 2];
  double sum = 0, sum2 = 0;
  int count = 0;
  for (double x : v) {
    if (x < half_level) continue;
    sum += x, sum2 += x * x, ++count;
  }
  if (count == 0 || sum <= 0) return 0;
  const double mean = sum / count;
  return 1.0 - std::sqrt(std::max(0.0, sum2 / count - mean * mean)) / mean;
}

// Throws unless there are two or more profiles of one non-empty grid.
void requireComparable(const std::vector<SurfaceProfile>& cycles) {
  if (cycles.size() < 2)
    throw std::invalid_argument(
        "kink detection needs profiles from at least 2 consecutive cycles, got " +
        std::to_string(cycles.size()));
  const SurfaceProfile& first = cycles.front();
  if (first.columns() < 1 || !(first.diameter > 0) || !(first.column_width > 0))
    throw std::invalid_argument("kink detection: empty profile or no positive diameter");
  for (const SurfaceProfile& p : cycles) {
    if (p.columns() != first.columns() || p.periodic_x != first.periodic_x ||
        p.column_width != first.column_width || p.diameter != first.diameter)
      throw std::invalid_argument(
          "kink detection: profiles differ in columns, width, diameter or boundary type");
  }
}

// Runs of equal non-zero sign of sAt(0 .. n-1) at least min_domain diameters wide (columns
// w wide, diameter d), equal neighbours merged; with periodic x the first and last meet
// across the start of the scan (the merged run then has a negative start).
template <class SignAt>
std::vector<Run> signedDomains(SignAt sAt, int n, double w, double d, bool periodic_x,
                               const KinkOptions& opt) {
  std::vector<Run> runs;
  for (int j = 0; j < n;) {
    if (sAt(j) == 0) {
      ++j;
      continue;
    }
    Run run{j, j, sAt(j)};
    while (run.end + 1 < n && sAt(run.end + 1) == run.sign) ++run.end;
    j = run.end + 1;
    if ((run.end - run.start + 1) * w >= opt.min_domain * d * (1 - 1e-12)) runs.push_back(run);
  }
  std::vector<Run> merged;
  for (const Run& run : runs) {
    if (!merged.empty() && merged.back().sign == run.sign)
      merged.back().end = run.end;
    else
      merged.push_back(run);
  }
  if (periodic_x && merged.size() >= 2 && merged.front().sign == merged.back().sign) {
    merged.front().start = merged.back().start - n;  // negative start: wraps
    merged.pop_back();
  }
  return merged;
}

}  // namespace

KinkResult detectKinks(const SurfaceProfile& cycle_a, const SurfaceProfile& cycle_b,
                       const KinkOptions& options) {
  return detectKinks(std::vector<SurfaceProfile>{cycle_a, cycle_b}, options);
}

KinkResult detectKinks(const std::vector<SurfaceProfile>& cycles, const KinkOptions& opt) {
  requireComparable(cycles);
  const SurfaceProfile& first = cycles.front();
  const int n = first.columns();
  const double d = first.diameter, w = first.column_width;

  KinkResult r;
  r.difference = periodTwoDifference(cycles);
  r.phase_sign.resize(n);
  for (int i = 0; i < n; ++i) {
    const double v = r.difference[i];
    r.phase_sign[i] = v > opt.dead_band * d ? 1 : (v < -opt.dead_band * d ? -1 : 0);
  }
  const std::vector<int>& s = r.phase_sign;

  // With periodic x, start the scan where s changes so that no run wraps around.
  int rot = 0;
  if (first.periodic_x) {
    rot = -1;
    for (int i = 0; i < n && rot < 0; ++i)
      if (s[i] != s[(i + n - 1) % n]) rot = i;
    if (rot < 0) rot = 0;  // uniform s: at most one domain, no kink
  }
  auto sAt = [&](int j) { return s[(rot + j) % n]; };

  const std::vector<Run> merged = signedDomains(sAt, n, w, d, first.periodic_x, opt);

  for (const Run& run : merged) {
    KinkDomain dom;
    dom.first_column = ((rot + run.start) % n + n) % n;
    dom.last_column = (rot + run.end) % n;
    dom.sign = run.sign;
    dom.width_d = (run.end - run.start + 1) * w / d;
    std::vector<double> v;
    for (int j = run.start; j <= run.end; ++j)
      v.push_back(run.sign * r.difference[((rot + j) % n + n) % n]);
    double mean = 0;
    for (double x : v) mean += x / static_cast<double>(v.size());
    dom.mean_difference_d = mean / d;
    dom.flatness = plateauFlatness(v);
    r.domains.push_back(dom);
  }

  // Kinks between neighbouring domains (opposite signs after merging) with flat plateaus.
  const int nd = static_cast<int>(merged.size());
  const int boundaries = first.periodic_x ? (nd >= 2 ? nd : 0) : nd - 1;
  const double length = first.width();
  for (int k = 0; k < boundaries; ++k) {
    const int k2 = (k + 1) % nd;
    if (r.domains[k].flatness < opt.min_flatness || r.domains[k2].flatness < opt.min_flatness)
      continue;
    const int e = merged[k].end;
    const int b = k2 > k ? merged[k2].start : merged[k2].start + n;
    const double pos = (rot + crossingPosition(r.difference, rot, e, b)) * w;
    r.kink_x.push_back(first.periodic_x ? pos - length * std::floor(pos / length) : pos);
  }
  if (first.periodic_x) std::sort(r.kink_x.begin(), r.kink_x.end());
  r.detected = !r.kink_x.empty();
  return r;
}

}  // namespace granwave
