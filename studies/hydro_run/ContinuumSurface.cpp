#include "studies/hydro_run/ContinuumSurface.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace granwave {

AreaFractionGrid continuumAreaFraction(const hydro::Hydro2DPhase& ph, const ContinuumColumns& c,
                                       const LayerSurfaceOptions& o) {
  const std::size_t nodes = static_cast<std::size_t>(c.columns) * (c.cells + 1);
  if (c.columns < 1 || c.cells < 1 || !(c.width > 0) || !(c.diameter > 0) ||
      ph.node_z.size() != nodes ||
      ph.area_fraction.size() != static_cast<std::size_t>(c.columns) * c.cells)
    throw std::invalid_argument("continuum surface: the phase does not fit its columns and cells");
  AreaFractionGrid g;
  g.columns = std::max(1, static_cast<int>(std::lround(c.width / c.diameter)));
  g.z_lo = 0;
  g.dz = o.z_bin * c.diameter;
  const double top = *std::max_element(ph.node_z.begin(), ph.node_z.end());
  g.bins = static_cast<int>(std::ceil((top + 3 * o.kernel_width * c.diameter) / g.dz)) + 1;
  g.phi.assign(static_cast<std::size_t>(g.columns) * g.bins, 0.0);
  // Each continuum column's bin means: the cells weighted by the part of the bin they cover.
  std::vector<double> mean(static_cast<std::size_t>(c.columns) * g.bins, 0.0);
  for (int i = 0; i < c.columns; ++i) {
    const double* z = ph.node_z.data() + static_cast<std::size_t>(i) * (c.cells + 1);
    const double* phi = ph.area_fraction.data() + static_cast<std::size_t>(i) * c.cells;
    int first = 0;  // the lowest cell reaching into the bin; bins ascend, so it only rises
    for (int b = 0; b < g.bins; ++b) {
      const double lo = g.z_lo + (b - 0.5) * g.dz, hi = lo + g.dz;
      while (first < c.cells && z[first + 1] <= lo) ++first;
      double sum = 0;
      for (int k = first; k < c.cells && z[k] < hi; ++k)
        sum += phi[k] * std::max(0.0, std::min(hi, z[k + 1]) - std::max(lo, z[k]));
      mean[static_cast<std::size_t>(i) * g.bins + b] = sum / g.dz;
    }
  }
  // Each surface column: the continuum columns weighted by the part of its width they cover
  // (one column when the continuum's are wider, several when they are narrower).
  const double dx = c.width / c.columns, column = c.width / g.columns;
  for (int s = 0; s < g.columns; ++s) {
    const double x0 = s * column, x1 = x0 + column;
    const int i1 = std::min(c.columns - 1, static_cast<int>(x1 / dx));
    for (int i = std::min(c.columns - 1, static_cast<int>(x0 / dx)); i <= i1; ++i) {
      const double w = std::max(0.0, std::min(x1, (i + 1) * dx) - std::max(x0, i * dx)) / column;
      for (int b = 0; b < g.bins; ++b)
        g.phi[static_cast<std::size_t>(s) * g.bins + b] +=
            w * mean[static_cast<std::size_t>(i) * g.bins + b];
    }
  }
  return g;
}

LayerSurface continuumSurface(const hydro::Hydro2DPhase& ph, const ContinuumColumns& c,
                              const LayerSurfaceOptions& o) {
  return layerSurfaceOfField(continuumAreaFraction(ph, c, o), c.width, c.diameter, c.periodic_x, o);
}

}  // namespace granwave
