#include "coarse_grain/HexaticOrder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace granwave {

namespace {

// The cells (ix +- reach, iz +- 1) of an nx x nz grid that exist, wrapped in x if periodic.
std::vector<std::size_t> cellStencil(int ix, int iz, int nx, int nz, int reach, bool periodic_x) {
  std::vector<std::size_t> cells;
  for (int jz = std::max(0, iz - 1); jz <= std::min(nz - 1, iz + 1); ++jz)
    for (int dx = -reach; dx <= reach; ++dx) {
      const int jx = ix + dx;
      if (jx >= 0 && jx < nx)
        cells.push_back(static_cast<std::size_t>(jz) * nx + jx);
      else if (periodic_x)
        cells.push_back(static_cast<std::size_t>(jz) * nx + (jx + nx) % nx);
    }
  return cells;
}

}  // namespace

std::vector<std::vector<int>> neighboursWithin(std::span<const double> x, std::span<const double> z,
                                               double cutoff, double width, bool periodic_x) {
  if (x.size() != z.size())
    throw std::invalid_argument("neighbour search: " + std::to_string(x.size()) + " x but " +
                                std::to_string(z.size()) + " z positions");
  if (!(cutoff > 0)) throw std::invalid_argument("neighbour search: cutoff must be positive");
  if (periodic_x && !(width > 0))
    throw std::invalid_argument("neighbour search: periodic x needs a positive width");
  const int n = static_cast<int>(x.size());
  std::vector<std::vector<int>> nb(n);
  if (n == 0) return nb;

  // Cells of side >= cutoff: every neighbour of a particle is in its cell or the 8 around.
  auto wrapped = [&](double v) { return periodic_x ? v - width * std::floor(v / width) : v; };
  double xlo = periodic_x ? 0.0 : x[0], xhi = periodic_x ? width : x[0];
  double zlo = z[0], zhi = z[0];
  for (int i = 0; i < n; ++i) {
    if (!periodic_x) xlo = std::min(xlo, x[i]), xhi = std::max(xhi, x[i]);
    zlo = std::min(zlo, z[i]), zhi = std::max(zhi, z[i]);
  }
  int nx = std::max(1, static_cast<int>((xhi - xlo) / cutoff));
  if (periodic_x && nx < 3) nx = 1;  // a 3-cell stencil would visit a cell twice
  const int nz = std::max(1, static_cast<int>((zhi - zlo) / cutoff));
  const double cx = (xhi - xlo) / nx, cz = (zhi - zlo) / nz;
  auto cellX = [&](double v) {
    return cx > 0 ? std::clamp(static_cast<int>((wrapped(v) - xlo) / cx), 0, nx - 1) : 0;
  };
  auto cellZ = [&](double v) {
    return cz > 0 ? std::clamp(static_cast<int>((v - zlo) / cz), 0, nz - 1) : 0;
  };
  std::vector<std::vector<int>> cell(static_cast<std::size_t>(nx) * nz);
  for (int i = 0; i < n; ++i)
    cell[static_cast<std::size_t>(cellZ(z[i])) * nx + cellX(x[i])].push_back(i);

  const double cut2 = cutoff * cutoff;
  const int reach = nx == 1 ? 0 : 1;
  for (int i = 0; i < n; ++i) {
    for (const std::size_t c : cellStencil(cellX(x[i]), cellZ(z[i]), nx, nz, reach, periodic_x))
      for (int k : cell[c]) {
        if (k == i) continue;
        double rx = x[k] - x[i];
        if (periodic_x) rx -= width * std::round(rx / width);
        const double rz = z[k] - z[i];
        if (rx * rx + rz * rz < cut2) nb[i].push_back(k);
      }
    std::sort(nb[i].begin(), nb[i].end());
  }
  return nb;
}

HexaticOrder hexaticOrder(std::span<const double> x, std::span<const double> z, double width,
                          double diameter, bool periodic_x, const HexaticOptions& opt) {
  if (!(diameter > 0)) throw std::invalid_argument("hexatic order: diameter must be positive");
  const std::vector<std::vector<int>> nb =
      neighboursWithin(x, z, opt.cutoff * diameter, width, periodic_x);
  const int n = static_cast<int>(x.size());
  HexaticOrder h;
  h.psi6.assign(n, 0.0);
  h.neighbours.assign(n, 0);
  std::complex<double> sum_psi = 0;
  double sum_abs = 0;
  for (int j = 0; j < n; ++j) {
    std::complex<double> psi = 0;
    for (int k : nb[j]) {
      double rx = x[k] - x[j];
      if (periodic_x) rx -= width * std::round(rx / width);
      psi += std::polar(1.0, 6.0 * std::atan2(z[k] - z[j], rx));
    }
    const int nj = static_cast<int>(nb[j].size());
    h.neighbours[j] = nj;
    if (nj > 0) h.psi6[j] = psi / static_cast<double>(nj);
    if (nj >= opt.min_neighbours && nj > 0) {
      ++h.counted;
      sum_abs += std::abs(h.psi6[j]);
      sum_psi += h.psi6[j];
    }
  }
  if (h.counted > 0) {
    h.mean_abs_psi6 = sum_abs / h.counted;
    h.abs_mean_psi6 = std::abs(sum_psi) / h.counted;
  }
  return h;
}

}  // namespace granwave
