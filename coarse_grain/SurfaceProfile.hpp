#pragma once
// Surface height h(x) of a vibrated layer in one snapshot (docs/classification.md, "Surface
// height h(x)"; paper Sec. III, Fig. 2).
//
// The container [0, L_x] is cut into n_columns columns of width w = L_x / n_columns (default:
// n_columns = round(L_x / d), one particle diameter each, the same columns as the field grid).
// In column i the surface is the top of the highest particle whose centre lies in the
// column, measured from the plate:
//
//     h_i = max_{k in column i} z_k + d/2 - z_b(t),        z_b(t) = snapshot.plate_height.
//
// h is thus the local layer thickness (the plate, not the lab, is the reference), so the
// same surface at the top and at the bottom of the plate's stroke gives the same h.
//
// Empty columns. A column of width <= d can be empty while the surface above it is closed
// (a disk of diameter d covers the column even when its centre lies next door), so an empty
// column is given the height of its neighbours, not zero: the linear interpolation between
// the nearest non-empty columns on either side, which for a single empty column is the
// average of its two neighbours. With side walls a run of empty columns touching a wall takes
// the height of the nearest non-empty column (zero slope at the wall, the condition a free
// surface meets at a vertical wall); with periodic x the interpolation wraps around. A layer
// with no particle at all has h = 0 everywhere. The result never holds NaN.
//
// Limitation: a single particle ballistically flying above the layer (saltation in a
// fluidised dry layer) sets its column's height. The wave and kink detectors pool many
// columns and cycles, which dilutes such spikes; see docs/classification.md.
#include <vector>

#include "particles/Snapshot.hpp"

namespace granwave {

struct SurfaceProfileOptions {
  int n_columns = 0;  // 0: round(L_x / d) columns, one particle diameter wide each
};

struct SurfaceProfile {
  double column_width = 0;     // m, w = L_x / n_columns
  double diameter = 0;         // m, particle diameter d (the unit of the detectors)
  bool periodic_x = false;     // periodic in x (else side walls at x = 0 and x = L_x)
  std::vector<double> height;  // m, h_i above the plate, i = 0 .. n_columns - 1
  int empty_columns = 0;       // columns without a particle centre, filled from neighbours

  int columns() const { return static_cast<int>(height.size()); }
  double width() const { return column_width * static_cast<double>(height.size()); }
  double columnCentre(int i) const { return (i + 0.5) * column_width; }  // m, lab frame x
};

// Throws std::invalid_argument for a non-positive width or diameter, n_columns < 0, or
// snapshot arrays x and z of different lengths.
SurfaceProfile surfaceProfile(const Snapshot& snapshot, double width, double diameter,
                              bool periodic_x, const SurfaceProfileOptions& options = {});

}  // namespace granwave
