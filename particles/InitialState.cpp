#include "particles/InitialState.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <unordered_map>

namespace granwave {

namespace {

void placeRandomly(InitialCondition& ic, int n, const EngineConfig& c, std::mt19937_64& rng) {
  const double d = c.diameter;
  const double xlo = c.periodic_x ? 0.0 : 0.5 * d, xhi = c.periodic_x ? c.width : c.width - 0.5 * d;
  const double zlo = c.periodic_z ? 0.0 : 0.5 * d,
               zhi = c.periodic_z ? c.height : c.height - 0.5 * d;
  std::uniform_real_distribution<double> ux(xlo, xhi), uz(zlo, zhi);
  // Hash grid of side d: any overlapping pair sits in neighbouring buckets.
  const int nbx = std::max(1, static_cast<int>(c.width / d));
  const int nbz = std::max(1, static_cast<int>(c.height / d));
  const double bx = c.width / nbx, bz = c.height / nbz;
  std::vector<std::vector<int>> bucket(static_cast<std::size_t>(nbx) * nbz);
  auto key = [&](int ix, int iz) { return static_cast<std::size_t>(iz) * nbx + ix; };
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
      const int ix = std::min(nbx - 1, static_cast<int>(x / bx));
      const int iz = std::min(nbz - 1, static_cast<int>(z / bz));
      bool free = true;
      for (int dz = -1; dz <= 1 && free; ++dz) {
        for (int dx = -1; dx <= 1 && free; ++dx) {
          int jx = ix + dx, jz = iz + dz;
          double sx = 0, sz = 0;
          if (jx < 0 || jx >= nbx) {
            if (!c.periodic_x) continue;
            sx = jx < 0 ? -c.width : c.width;
            jx = (jx + nbx) % nbx;
          }
          if (jz < 0 || jz >= nbz) {
            if (!c.periodic_z) continue;
            sz = jz < 0 ? -c.height : c.height;
            jz = (jz + nbz) % nbz;
          }
          for (int j : bucket[key(jx, jz)]) {
            const double rx = x - ic.x[j] - sx, rz = z - ic.z[j] - sz;
            if (rx * rx + rz * rz < d * d) free = false;
          }
        }
      }
      if (!free) continue;
      ic.x.push_back(x);
      ic.z.push_back(z);
      bucket[key(ix, iz)].push_back(i);
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
