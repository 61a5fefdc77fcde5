#include "coarse_grain/LayerSurface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace granwave {

namespace {

// Weights of a unit Gaussian (standard deviation `sigma`, in grid units) centred `offset` grid
// units right of grid point 0, at grid points -reach .. reach, normalised to sum 1 (the disk's
// area is conserved). exp(-(j - u)^2 / 2s^2) = exp(-u^2/2s^2) exp(u j/s^2) exp(-j^2/2s^2): two
// exponentials per particle and axis instead of one per grid point.
void gaussianWeights(double offset, double sigma, int reach, const std::vector<double>& quad,
                     std::vector<double>& w) {
  const double inv = 1.0 / (sigma * sigma);
  const double base = std::exp(-0.5 * offset * offset * inv);
  const double step = std::exp(offset * inv);
  const double back = 1.0 / step;
  double sum = 0;
  w[reach] = base;
  double up = base, down = base;
  for (int j = 1; j <= reach; ++j) {
    up *= step;
    down *= back;
    w[reach + j] = up * quad[j];
    w[reach - j] = down * quad[j];
  }
  for (double v : w) sum += v;
  for (double& v : w) v /= sum;
}

// Column of grid index j: wrapped for periodic x, mirrored at side walls (the kernel's mass
// beyond a wall is reflected back, so a disk at the wall keeps its whole area).
int columnIndex(int j, int n, bool periodic_x) {
  if (periodic_x) return ((j % n) + n) % n;
  if (j < 0) j = -1 - j;
  if (j >= n) j = 2 * n - 1 - j;
  return std::clamp(j, 0, n - 1);
}

void checkArguments(const Snapshot& s, double width, double d, const LayerSurfaceOptions& o) {
  if (!(width > 0) || !(d > 0))
    throw std::invalid_argument(
        "layer surface needs a positive container width and diameter, got width = " +
        std::to_string(width) + " m, d = " + std::to_string(d) + " m");
  if (!(o.kernel_width > 0) || !(o.z_bin > 0))
    throw std::invalid_argument("layer surface: kernel_width and z_bin must be positive (in d)");
  if (!(o.fraction > 0 && o.fraction < 1))
    throw std::invalid_argument("layer surface: fraction must lie in (0, 1), got " +
                                std::to_string(o.fraction));
  if (s.x.size() != s.z.size())
    throw std::invalid_argument("layer surface: snapshot has " + std::to_string(s.x.size()) +
                                " x but " + std::to_string(s.z.size()) + " z positions");
}

AreaFractionGrid coarseGrain(const Snapshot& s, double width, double d, bool periodic_x, int n,
                             const LayerSurfaceOptions& o) {
  AreaFractionGrid g;
  g.columns = n;
  g.dz = o.z_bin * d;
  const double w = width / n, sigma = o.kernel_width * d;
  double lo = 1e300, hi = -1e300;
  for (double z : s.z) {
    lo = std::min(lo, z - s.plate_height);
    hi = std::max(hi, z - s.plate_height);
  }
  const double margin = 4 * sigma;
  g.z_lo = lo - margin;
  g.bins = static_cast<int>(std::ceil((hi - lo + 2 * margin) / g.dz)) + 1;
  g.phi.assign(static_cast<std::size_t>(n) * g.bins, 0.0);

  const int rx = static_cast<int>(std::ceil(3 * sigma / w));
  const int rz = static_cast<int>(std::ceil(3 * sigma / g.dz));
  const double sx = sigma / w, sz = sigma / g.dz;
  std::vector<double> qx(rx + 1), qz(rz + 1), wx(2 * rx + 1), wz(2 * rz + 1);
  for (int j = 0; j <= rx; ++j) qx[j] = std::exp(-0.5 * j * j / (sx * sx));
  for (int j = 0; j <= rz; ++j) qz[j] = std::exp(-0.5 * j * j / (sz * sz));
  // Each grid cell of w x dz holding one disk's area in full has phi = area / (w dz).
  const double density = 0.25 * std::numbers::pi * d * d / (w * g.dz);
  std::vector<int> cols(2 * rx + 1);
  for (std::size_t k = 0; k < s.x.size(); ++k) {
    double x = s.x[k];
    if (periodic_x) x -= width * std::floor(x / width);
    const double u = x / w - 0.5;  // column-centre units
    const int i0 = static_cast<int>(std::lround(u));
    const double v = (s.z[k] - s.plate_height - g.z_lo) / g.dz;
    const int b0 = static_cast<int>(std::lround(v));
    gaussianWeights(u - i0, sx, rx, qx, wx);
    gaussianWeights(v - b0, sz, rz, qz, wz);
    for (int a = -rx; a <= rx; ++a) cols[a + rx] = columnIndex(i0 + a, n, periodic_x);
    for (int a = -rx; a <= rx; ++a) {
      double* row = g.phi.data() + static_cast<std::size_t>(cols[a + rx]) * g.bins;
      const double f = density * wx[a + rx];
      for (int b = -rz; b <= rz; ++b) {
        const int bin = b0 + b;
        if (bin >= 0 && bin < g.bins) row[bin] += f * wz[b + rz];
      }
    }
  }
  return g;
}

// Height above the plate where column i's phi first falls through `level` going up from its
// densest bin; 0 if it never reaches the level.
double crossing(const AreaFractionGrid& g, int i, double level, bool& thin) {
  int top = 0;
  for (int b = 1; b < g.bins; ++b)
    if (g.at(i, b) > g.at(i, top)) top = b;
  thin = g.at(i, top) < level;
  if (thin) return 0.0;
  int b = top;
  while (b + 1 < g.bins && g.at(i, b + 1) >= level) ++b;
  if (b + 1 >= g.bins) return g.z_lo + b * g.dz;
  const double f0 = g.at(i, b), f1 = g.at(i, b + 1);
  return g.z_lo + (b + (f0 - level) / (f0 - f1)) * g.dz;
}

// The bulk value and each column's crossing of the grid (the header's rule).
void surfaceOfGrid(const AreaFractionGrid& g, const LayerSurfaceOptions& o, LayerSurface& r) {
  const int n = g.columns;
  std::vector<double> peak(n);
  for (int i = 0; i < n; ++i) {
    peak[i] = 0;
    for (int b = 0; b < g.bins; ++b) peak[i] = std::max(peak[i], g.at(i, b));
  }
  std::vector<double> sorted = peak;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  r.bulk_area_fraction = sorted[n / 2];
  const double level = o.fraction * r.bulk_area_fraction;
  for (int i = 0; i < n; ++i) {
    bool thin = false;
    r.profile.height[i] = crossing(g, i, level, thin);
    r.thin_columns += thin;
  }
}

// phi blurred by the particles' kernel along x (wrapped or mirrored as their deposit) and z.
void blur(AreaFractionGrid& g, double width, double d, bool periodic_x,
          const LayerSurfaceOptions& o) {
  const double sigma = o.kernel_width * d, w = width / g.columns;
  const double sx = sigma / w, sz = sigma / g.dz;
  const int rx = static_cast<int>(std::ceil(3 * sx)), rz = static_cast<int>(std::ceil(3 * sz));
  std::vector<double> qx(rx + 1), qz(rz + 1), wx(2 * rx + 1), wz(2 * rz + 1);
  for (int j = 0; j <= rx; ++j) qx[j] = std::exp(-0.5 * j * j / (sx * sx));
  for (int j = 0; j <= rz; ++j) qz[j] = std::exp(-0.5 * j * j / (sz * sz));
  gaussianWeights(0.0, sx, rx, qx, wx);
  gaussianWeights(0.0, sz, rz, qz, wz);
  std::vector<double> along_x(g.phi.size(), 0.0);
  for (int i = 0; i < g.columns; ++i)
    for (int a = -rx; a <= rx; ++a) {
      const int c = columnIndex(i + a, g.columns, periodic_x);
      for (int b = 0; b < g.bins; ++b)
        along_x[static_cast<std::size_t>(c) * g.bins + b] += wx[a + rx] * g.at(i, b);
    }
  std::fill(g.phi.begin(), g.phi.end(), 0.0);
  for (int i = 0; i < g.columns; ++i)
    for (int b = 0; b < g.bins; ++b)
      for (int a = -rz; a <= rz; ++a)
        if (b + a >= 0 && b + a < g.bins)
          g.phi[static_cast<std::size_t>(i) * g.bins + b + a] +=
              wz[a + rz] * along_x[static_cast<std::size_t>(i) * g.bins + b];
}

LayerSurface emptySurface(double width, double d, bool periodic_x, int n) {
  LayerSurface r;
  r.profile.column_width = width / n;
  r.profile.diameter = d;
  r.profile.periodic_x = periodic_x;
  r.profile.height.assign(n, 0.0);
  return r;
}

}  // namespace

LayerSurface layerSurface(const Snapshot& s, double width, double d, bool periodic_x,
                          const LayerSurfaceOptions& o) {
  checkArguments(s, width, d, o);
  const int n = std::max(1, static_cast<int>(std::lround(width / d)));
  LayerSurface r = emptySurface(width, d, periodic_x, n);
  if (s.x.empty()) {
    r.thin_columns = n;
    return r;
  }
  surfaceOfGrid(coarseGrain(s, width, d, periodic_x, n, o), o, r);
  return r;
}

LayerSurface layerSurfaceOfField(AreaFractionGrid g, double width, double d, bool periodic_x,
                                 const LayerSurfaceOptions& o) {
  checkArguments(Snapshot{}, width, d, o);
  const int n = std::max(1, static_cast<int>(std::lround(width / d)));
  if (g.columns != n || g.bins < 1 || !(g.dz > 0) ||
      g.phi.size() != static_cast<std::size_t>(g.columns) * g.bins)
    throw std::invalid_argument("layer surface of a field: the grid must have " +
                                std::to_string(n) + " columns and a phi per column and bin");
  LayerSurface r = emptySurface(width, d, periodic_x, n);
  blur(g, width, d, periodic_x, o);
  surfaceOfGrid(g, o, r);
  return r;
}

}  // namespace granwave
