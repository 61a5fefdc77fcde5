#pragma once
// The lab-frame grid of the coarse-graining (paper, Sec. IV; docs/fields.md, "Definitions"):
// N_x = L_x / d columns, N_z = ceil((L_z + 2A) / d) rows of side d, covering z from -A
// (the lowest plate position) to -A + N_z d >= L_z + A.
#include <algorithm>
#include <cmath>

namespace granwave {

struct FieldGrid {
  int nx = 1, nz = 1;
  double x0 = 0, z0 = 0;  // lower-left corner, m
  double wx = 1, wz = 1;  // cell sizes, m

  static FieldGrid forContainer(double width, double height, double amplitude, double d) {
    FieldGrid g;
    g.nx = std::max(1, static_cast<int>(std::lround(width / d)));
    g.wx = width / g.nx;
    g.nz = std::max(1, static_cast<int>(std::ceil((height + 2.0 * amplitude) / d - 1e-9)));
    g.wz = d;
    g.z0 = -amplitude;
    return g;
  }
  int cells() const { return nx * nz; }
  // Cell of a point, or -1 outside the grid.
  int cellOf(double x, double z) const {
    const int i = static_cast<int>(std::floor((x - x0) / wx));
    const int j = static_cast<int>(std::floor((z - z0) / wz));
    if (i < 0 || i >= nx || j < 0 || j >= nz) return -1;
    return j * nx + i;
  }
  double xCentre(int i) const { return x0 + (i + 0.5) * wx; }
  double zCentre(int j) const { return z0 + (j + 0.5) * wz; }
};

}  // namespace granwave
