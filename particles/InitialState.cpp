#include "particles/InitialState.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace granwave {

namespace {

// A neighbour bucket index j of n along one axis: wrapped (with the image shift) if the axis is
// periodic; false if it lies beyond a wall.
bool neighbourBucket(int& j, double& shift, int n, bool periodic, double length) {
  shift = 0;
  if (j >= 0 && j < n) return true;
  if (!periodic) return false;
  shift = j < 0 ? -length : length;
  j = (j + n) % n;
  return true;
}

// Hash grid of side >= d over the box: any overlapping pair sits in neighbouring buckets.
class PlacementGrid {
 public:
  explicit PlacementGrid(const EngineConfig& c)
      : c_(c),
        nbx_(std::max(1, static_cast<int>(c.width / c.diameter))),
        nbz_(std::max(1, static_cast<int>(c.height / c.diameter))),
        bucket_(static_cast<std::size_t>(nbx_) * nbz_) {}

  // True if a disk at (x, z) overlaps none of the disks placed so far.
  bool fits(const InitialCondition& ic, double x, double z) const {
    const auto [ix, iz] = bucketOf(x, z);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dx = -1; dx <= 1; ++dx)
        if (overlapsBucket(ic, x, z, ix + dx, iz + dz)) return false;
    return true;
  }
  void add(double x, double z, int i) {
    const auto [ix, iz] = bucketOf(x, z);
    bucket_[key(ix, iz)].push_back(i);
  }

 private:
  std::pair<int, int> bucketOf(double x, double z) const {
    return {std::min(nbx_ - 1, static_cast<int>(x / (c_.width / nbx_))),
            std::min(nbz_ - 1, static_cast<int>(z / (c_.height / nbz_)))};
  }
  std::size_t key(int ix, int iz) const { return static_cast<std::size_t>(iz) * nbx_ + ix; }
  bool overlapsBucket(const InitialCondition& ic, double x, double z, int jx, int jz) const {
    double sx = 0, sz = 0;
    if (!neighbourBucket(jx, sx, nbx_, c_.periodic_x, c_.width) ||
        !neighbourBucket(jz, sz, nbz_, c_.periodic_z, c_.height))
      return false;
    const double d = c_.diameter;
    for (int j : bucket_[key(jx, jz)]) {
      const double rx = x - ic.x[j] - sx, rz = z - ic.z[j] - sz;
      if (rx * rx + rz * rz < d * d) return true;
    }
    return false;
  }

  const EngineConfig& c_;
  int nbx_, nbz_;
  std::vector<std::vector<int>> bucket_;
};

void placeRandomly(InitialCondition& ic, int n, const EngineConfig& c, std::mt19937_64& rng) {
  const double d = c.diameter;
  const double xlo = c.periodic_x ? 0.0 : 0.5 * d, xhi = c.periodic_x ? c.width : c.width - 0.5 * d;
  const double zlo = c.periodic_z ? 0.0 : 0.5 * d,
               zhi = c.periodic_z ? c.height : c.height - 0.5 * d;
  std::uniform_real_distribution<double> ux(xlo, xhi), uz(zlo, zhi);
  PlacementGrid grid(c);
  const long max_attempts = 2000L * n + 100000L;
  long attempts = 0;
  for (int i = 0; i < n; ++i) {
    for (;;) {
      if (++attempts > max_attempts)
        throw std::invalid_argument(fmt::format(
            "initial.placement = \"random\" could place only {} of {} particles without overlap; "
            "use initial.placement = \"lattice\" or a larger container",
            i, n));
      const double x = ux(rng), z = uz(rng);
      if (!grid.fits(ic, x, z)) continue;
      ic.x.push_back(x);
      ic.z.push_back(z);
      grid.add(x, z, i);
      break;
    }
  }
}

void placeOnLattice(InitialCondition& ic, int n, const EngineConfig& c) {
  const double d = c.diameter;
  if (c.periodic_x && c.periodic_z) {
    // Square lattice spread over the whole periodic box.
    const int cols = static_cast<int>(std::ceil(std::sqrt(n * c.width / c.height)));
    const int rows = (n + cols - 1) / cols;
    const double ax = c.width / cols, az = c.height / rows;
    if (ax < d || az < d)
      throw std::invalid_argument(fmt::format(
          "initial.placement = \"lattice\": {} particles do not fit on a square lattice in the "
          "periodic box (spacing {:.4g} x {:.4g} m < d)",
          n, ax, az));
    for (int i = 0; i < n; ++i) {
      ic.x.push_back((i % cols + 0.5) * ax);
      ic.z.push_back((i / cols + 0.5) * az);
    }
    return;
  }
  // Triangular lattice resting on the bottom, rows filled from below.
  const double s = d * (1.0 + 1e-6);
  const double row = s * std::sqrt(3.0) / 2.0;
  const double x0 = c.periodic_x ? 0.0 : 0.5 * d;
  const double xmax = c.periodic_x ? c.width - s : c.width - 0.5 * d;
  int i = 0;
  for (int r = 0; i < n; ++r) {
    const double z = 0.5 * d + r * row;
    if (z > c.height - 0.5 * d)
      throw std::invalid_argument(fmt::format(
          "initial.placement = \"lattice\": only {} of {} particles fit in the container", i, n));
    for (double x = x0 + (r % 2) * 0.5 * s; x <= xmax + 1e-12 && i < n; x += s, ++i) {
      ic.x.push_back(x);
      ic.z.push_back(z);
    }
  }
}

}  // namespace

InitialCondition initialCondition(const Scene& scene, const EngineConfig& c) {
  const int n = scene.particles.count;
  std::mt19937_64 rng(scene.run.seed);
  InitialCondition ic;
  ic.x.reserve(n);
  ic.z.reserve(n);
  if (scene.initial.placement == InitialPlacement::Lattice) {
    placeOnLattice(ic, n, c);
  } else {
    placeRandomly(ic, n, c, rng);
  }
  ic.vx.resize(n);
  ic.vz.resize(n);
  ic.omega.assign(n, 0.0);
  if (scene.initial.temperature && *scene.initial.temperature > 0) {
    const double T = *scene.initial.temperature;
    std::normal_distribution<double> normal(0.0, std::sqrt(T / c.mass));
    double mx = 0, mz = 0;
    for (int i = 0; i < n; ++i) {
      ic.vx[i] = normal(rng);
      ic.vz[i] = normal(rng);
      mx += ic.vx[i] / n;
      mz += ic.vz[i] / n;
    }
    double ke = 0;
    for (int i = 0; i < n; ++i) {
      if (n > 1) {
        ic.vx[i] -= mx;
        ic.vz[i] -= mz;
      }
      ke += 0.5 * c.mass * (ic.vx[i] * ic.vx[i] + ic.vz[i] * ic.vz[i]);
    }
    const double scale = ke > 0 ? std::sqrt(n * T / ke) : 0.0;
    for (int i = 0; i < n; ++i) {
      ic.vx[i] *= scale;
      ic.vz[i] *= scale;
    }
  } else {
    const double vmax = 1e-2 * std::sqrt(c.gravity * c.diameter);
    std::uniform_real_distribution<double> speed(0.0, vmax), angle(0.0, 2.0 * std::numbers::pi);
    for (int i = 0; i < n; ++i) {
      const double v = speed(rng), a = angle(rng);
      ic.vx[i] = v * std::cos(a);
      ic.vz[i] = v * std::sin(a);
    }
  }
  return ic;
}

}  // namespace granwave
