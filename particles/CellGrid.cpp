#include "particles/CellGrid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace granwave {

int cellsAlong(double length, double min_side) {
  return std::max(1, static_cast<int>(std::floor(length / min_side)));
}

CellGrid::CellGrid(const CellGeometry& g, int particles)
    : g_(g), slots_(static_cast<std::size_t>(g.nx) * g.nz * stride_, 0), cell_(particles, -1) {}

int CellGrid::locate(double x, double z) const {
  const int cx = std::clamp(static_cast<int>(std::floor((x - g_.x0) / g_.wx)), 0, g_.nx - 1);
  const int cz = std::clamp(static_cast<int>(std::floor((z - g_.z0) / g_.wz)), 0, g_.nz - 1);
  return index(cx, cz);
}

void CellGrid::insert(int p, int cell) {
  if (slots_[static_cast<std::size_t>(cell) * stride_] == capacity()) grow();
  int* block = &slots_[static_cast<std::size_t>(cell) * stride_];
  const int n = block[0];
  std::copy_backward(block + 1, block + 1 + n, block + 2 + n);
  block[1] = p;
  block[0] = n + 1;
  cell_[p] = cell;
}

void CellGrid::remove(int p) {
  int* block = &slots_[static_cast<std::size_t>(cell_[p]) * stride_];
  int* members = block + 1;
  int* end = members + block[0];
  int* at = std::find(members, end, p);
  std::copy(at + 1, end, at);
  --block[0];
  cell_[p] = -1;
}

void CellGrid::grow() {
  const int stride = 2 * stride_;
  std::vector<int> slots(slots_.size() / stride_ * stride, 0);
  for (std::size_t c = 0; c < slots_.size() / stride_; ++c)
    std::copy_n(&slots_[c * stride_], stride_, &slots[c * stride]);
  slots_ = std::move(slots);
  stride_ = stride;
}

CellGrid::Lists CellGrid::lists() const {
  const std::size_t cells = slots_.size() / stride_;
  Lists out{std::vector<int>(cells, -1), std::vector<int>(cell_.size(), -1),
            std::vector<int>(cell_.size(), -1), cell_};
  for (std::size_t c = 0; c < cells; ++c) {
    const std::span<const int> m = members(static_cast<int>(c));
    if (m.empty()) continue;
    out.head[c] = m[0];
    for (std::size_t k = 1; k < m.size(); ++k) {
      out.next[m[k - 1]] = m[k];
      out.prev[m[k]] = m[k - 1];
    }
  }
  return out;
}

void CellGrid::restore(const Lists& saved) {
  const std::size_t n = cell_.size(), cells = slots_.size() / stride_;
  if (saved.head.size() != cells || saved.next.size() != n || saved.prev.size() != n ||
      saved.cell.size() != n)
    throw std::invalid_argument("cell lists: saved for " + std::to_string(saved.head.size()) +
                                " cells and " + std::to_string(saved.cell.size()) +
                                " particles, the grid has " + std::to_string(cells) + " and " +
                                std::to_string(n));
  // Walk every list: each particle must be reached exactly once, in the cell it names.
  std::vector<char> seen(n, 0);
  std::size_t reached = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    int previous = -1;
    for (int p = saved.head[c]; p >= 0; p = saved.next[p]) {
      if (static_cast<std::size_t>(p) >= n || seen[p] || saved.cell[p] != static_cast<int>(c) ||
          saved.prev[p] != previous)
        throw std::invalid_argument("cell lists: inconsistent at cell " + std::to_string(c));
      seen[p] = 1;
      ++reached;
      previous = p;
    }
  }
  if (reached != n)
    throw std::invalid_argument("cell lists: " + std::to_string(n - reached) +
                                " particles are in no cell");
  // Valid: fill the blocks, each cell's list in order (insert puts a particle in front, so
  // its members go in from the last).
  std::fill(slots_.begin(), slots_.end(), 0);
  std::vector<int> members;
  for (std::size_t c = 0; c < cells; ++c) {
    members.clear();
    for (int p = saved.head[c]; p >= 0; p = saved.next[p]) members.push_back(p);
    for (auto p = members.rbegin(); p != members.rend(); ++p) insert(*p, static_cast<int>(c));
  }
}

int CellGrid::newNeighbours(int cell, int step_x, int step_z, Neighbour out[3]) const {
  const int cx0 = cx(cell), cz0 = cz(cell);
  if (cx0 > 0 && cx0 + 1 < g_.nx && cz0 > 0 && cz0 + 1 < g_.nz) {
    // Interior cell: no wrapping, no shifts.
    const int far = cell + step_x + step_z * g_.nx;
    const int along = step_x != 0 ? g_.nx : 1;
    out[0] = {far - along, 0.0, 0.0};
    out[1] = {far, 0.0, 0.0};
    out[2] = {far + along, 0.0, 0.0};
    return 3;
  }
  int n = 0;
  for (int k = -1; k <= 1; ++k) {
    int cx1 = cx0 + (step_x != 0 ? step_x : k);
    int cz1 = cz0 + (step_z != 0 ? step_z : k);
    double sx = 0, sz = 0;
    if (cx1 < 0 || cx1 >= g_.nx) {
      if (!g_.periodic_x) continue;
      sx = cx1 < 0 ? -g_.lx() : g_.lx();
      cx1 = (cx1 + g_.nx) % g_.nx;
    }
    if (cz1 < 0 || cz1 >= g_.nz) {
      if (!g_.periodic_z) continue;
      sz = cz1 < 0 ? -g_.lz() : g_.lz();
      cz1 = (cz1 + g_.nz) % g_.nz;
    }
    out[n++] = {index(cx1, cz1), sx, sz};
  }
  return n;
}

int CellGrid::neighbours(int cell, Neighbour out[9]) const {
  const int cx0 = cx(cell), cz0 = cz(cell);
  if (cx0 > 0 && cx0 + 1 < g_.nx && cz0 > 0 && cz0 + 1 < g_.nz) {
    // Interior cell (almost all of them): no wrapping, no shifts.
    const int nx = g_.nx;
    int n = 0;
    for (int dz = -nx; dz <= nx; dz += nx)
      for (int dx = -1; dx <= 1; ++dx) out[n++] = {cell + dz + dx, 0.0, 0.0};
    return 9;
  }
  int n = 0;
  for (int dz = -1; dz <= 1; ++dz) {
    int cz1 = cz0 + dz;
    double sz = 0;
    if (cz1 < 0 || cz1 >= g_.nz) {
      if (!g_.periodic_z) continue;
      sz = cz1 < 0 ? -g_.lz() : g_.lz();
      cz1 = (cz1 + g_.nz) % g_.nz;
    }
    for (int dx = -1; dx <= 1; ++dx) {
      int cx1 = cx0 + dx;
      double sx = 0;
      if (cx1 < 0 || cx1 >= g_.nx) {
        if (!g_.periodic_x) continue;
        sx = cx1 < 0 ? -g_.lx() : g_.lx();
        cx1 = (cx1 + g_.nx) % g_.nx;
      }
      out[n++] = {index(cx1, cz1), sx, sz};
    }
  }
  return n;
}

}  // namespace granwave
