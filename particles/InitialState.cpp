#include "particles/InitialState.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "scene/PlacementCapacity.hpp"
#include "scene/SceneParser.hpp"

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
        throw SceneError(fmt::format(
            "particles.count = {}: initial.placement = \"random\" could place only {} without "
            "overlap in {} attempts (random placement jams below {} of the area); use "
            "initial.placement = \"lattice\", fewer particles or a larger container",
            n, i, max_attempts, kRandomJammingCoverage));
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
    const SquareLattice lattice(n, c.width, c.height);
    if (!lattice.fits(d))
      throw SceneError(fmt::format(
          "initial.placement = \"lattice\": {} particles do not fit on a square lattice in the "
          "periodic box (spacing {:.4g} x {:.4g} m < d)",
          n, lattice.spacing_x, lattice.spacing_z));
    for (int i = 0; i < n; ++i) {
      ic.x.push_back((i % lattice.columns + 0.5) * lattice.spacing_x);
      ic.z.push_back((i / lattice.columns + 0.5) * lattice.spacing_z);
    }
    return;
  }
  // Triangular lattice resting on the bottom, rows filled from below (scene/PlacementCapacity).
  const TriangularLattice lattice(c.width, c.height, d, c.periodic_x);
  int i = 0;
  for (int r = 0; i < n; ++r) {
    if (r >= lattice.rows())
      throw SceneError(fmt::format(
          "initial.placement = \"lattice\": only {} of {} particles fit in the container", i, n));
    for (int k = 0; k < lattice.sites(r) && i < n; ++k, ++i) {
      ic.x.push_back(lattice.x0(r) + k * lattice.spacing());
      ic.z.push_back(lattice.z(r));
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
