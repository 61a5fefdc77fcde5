#include "coarse_grain/SurfaceProfile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace granwave {

namespace {

// Column of a particle centre: wrapped for periodic x, clamped onto the end columns at walls
// (a centre exactly at x = L_x, or a hair outside by round-off, belongs to the last column).
int columnOf(double x, double w, int n, double width, bool periodic_x) {
  if (periodic_x) x -= width * std::floor(x / width);
  const int i = static_cast<int>(std::floor(x / w));
  return periodic_x ? (i % n + n) % n : std::clamp(i, 0, n - 1);
}

// Fill the empty columns (marked by `filled[i] == false`) by linear interpolation between the
// nearest filled columns; runs touching a wall copy the nearest filled column.
void fillEmptyColumns(std::vector<double>& h, const std::vector<bool>& filled, bool periodic_x) {
  const int n = static_cast<int>(h.size());
  int first = -1;
  for (int i = 0; i < n && first < 0; ++i)
    if (filled[i]) first = i;
  if (first < 0) {  // no particle: a layer of zero thickness
    std::fill(h.begin(), h.end(), 0.0);
    return;
  }
  // Walk the filled columns in order; between two consecutive filled columns a and b
  // (b after a, wrapping for periodic x) interpolate linearly.
  int a = first;
  for (int step = 1; step <= n; ++step) {
    const int b = (first + step) % n;
    if (!filled[b]) continue;
    int gap = (b - a + n) % n;  // columns from a to b going right
    if (gap == 0) gap = n;      // one filled column: the run goes all the way round
    const bool wraps = b <= a;
    if (gap > 1) {
      for (int s = 1; s < gap; ++s) {
        const int i = (a + s) % n;
        if (wraps && !periodic_x) {
          // Run touching a wall (right of the last filled column or left of the first one).
          h[i] = (a + s < n) ? h[a] : h[b];
        } else {
          const double t = static_cast<double>(s) / gap;
          h[i] = (1.0 - t) * h[a] + t * h[b];
        }
      }
    }
    a = b;
    if (b == first) break;
  }
}

}  // namespace

SurfaceProfile surfaceProfile(const Snapshot& snapshot, double width, double diameter,
                              bool periodic_x, const SurfaceProfileOptions& options) {
  if (!(width > 0) || !(diameter > 0))
    throw std::invalid_argument(
        "surface profile needs a positive container width and diameter, got width = " +
        std::to_string(width) + " m, d = " + std::to_string(diameter) + " m");
  if (options.n_columns < 0)
    throw std::invalid_argument("surface profile: n_columns must be >= 0 (0: one per diameter)");
  if (snapshot.x.size() != snapshot.z.size())
    throw std::invalid_argument("surface profile: snapshot has " +
                                std::to_string(snapshot.x.size()) + " x but " +
                                std::to_string(snapshot.z.size()) + " z positions");

  const int n = options.n_columns > 0
                    ? options.n_columns
                    : std::max(1, static_cast<int>(std::lround(width / diameter)));
  SurfaceProfile p;
  p.column_width = width / n;
  p.diameter = diameter;
  p.periodic_x = periodic_x;
  p.height.assign(n, -std::numeric_limits<double>::infinity());

  std::vector<bool> filled(n, false);
  for (std::size_t k = 0; k < snapshot.x.size(); ++k) {
    const int i = columnOf(snapshot.x[k], p.column_width, n, width, periodic_x);
    p.height[i] = std::max(p.height[i], snapshot.z[k] + 0.5 * diameter - snapshot.plate_height);
    filled[i] = true;
  }
  p.empty_columns = static_cast<int>(std::count(filled.begin(), filled.end(), false));
  fillEmptyColumns(p.height, filled, periodic_x);
  return p;
}

}  // namespace granwave
