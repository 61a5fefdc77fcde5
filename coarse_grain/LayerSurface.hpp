#pragma once
// The free surface of a vibrated layer in one snapshot, from its coarse-grained area fraction
// (docs/classification.md, "The layer's surface from its area fraction").
//
// Each disk's area pi d^2/4 is spread over the plane by a Gaussian of width `kernel_width`
// (the coarse-graining of Weinhart, Thornton, Luding & Bokhove, Granular Matter 14, 289
// (2012), Sec. 2: a kernel narrower than a particle blurs the discreteness, one much wider
// blurs the field), giving the area fraction phi(x, z) on the columns of SurfaceProfile (one d
// wide) and on z bins of `z_bin` above the plate. The layer's bulk value phi_b is the median
// over the columns of each column's largest phi. In column i the surface is where phi, going
// up from the column's densest bin, first falls through `fraction` phi_b (linear between
// bins), measured from the plate:
//
//     h_i = min { z > z_max,i : phi_i(z) = fraction phi_b } - z_b(t).
//
// Why this and not the top particle per column (SurfaceProfile): one particle flying above a
// fluidised layer sets the top-particle height of its column however far up it is, so a gas of
// saltating grains makes a rough surface of spikes whose spectrum has no wavelength. A lone
// disk, seen through the kernel, reaches at most phi = (pi d^2/4)/(2 pi s^2) = 1/2 at s = d/2,
// and it is cut off from the layer by the dilute gap below it: the half-bulk crossing stops at
// the gap. For a dense packing the crossing lies where the point density of the disk centres
// falls to half, half a row spacing above the top row's centres (0.43 d for a triangular
// packing), close to the top-particle height (0.5 d above them).
//
// A column whose phi never reaches fraction phi_b (a trough emptied by a wave, or a dilute
// gas) has no layer above that level: h_i = 0, counted in `thin_columns`.
#include <vector>

#include "coarse_grain/SurfaceProfile.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

struct LayerSurfaceOptions {
  double kernel_width = 0.5;  // d, standard deviation of the Gaussian coarse-graining kernel
  double z_bin = 0.25;        // d, vertical resolution of phi before the crossing is interpolated
  double fraction = 0.5;      // of the bulk area fraction: the surface's level
};

struct LayerSurface {
  SurfaceProfile profile;         // h_i above the plate (columns as SurfaceProfile's)
  double bulk_area_fraction = 0;  // phi_b
  int thin_columns = 0;           // columns never reaching fraction phi_b (h_i = 0)
};

// Throws std::invalid_argument for a non-positive width or diameter, non-positive kernel or
// bin, a fraction outside (0, 1), or snapshot arrays x and z of different lengths.
LayerSurface layerSurface(const Snapshot& snapshot, double width, double diameter, bool periodic_x,
                          const LayerSurfaceOptions& options = {});

// The area fraction phi[column][bin] on the surface's columns (round(width / d) of them) and on
// bins of z_bin d from z_lo above the plate (bin b centred at z_lo + b dz): what the particles'
// kernel makes of them, or a continuum's field sampled at the bin centres.
struct AreaFractionGrid {
  int columns = 0, bins = 0;
  double z_lo = 0, dz = 0;  // m
  std::vector<double> phi;
  double at(int i, int b) const { return phi[static_cast<std::size_t>(i) * bins + b]; }
};

// The surface of a field's layer by the same rule as layerSurface: a continuum's area
// fraction, sampled on the grid, is first blurred by the kernel the particles' area is spread
// with (the same normalised Gaussian weights, wrapped for periodic x, mirrored at side walls),
// then its bulk value and crossings are found as for particles. The grid's columns must be
// round(width / diameter). Throws std::invalid_argument as layerSurface.
LayerSurface layerSurfaceOfField(AreaFractionGrid field, double width, double diameter,
                                 bool periodic_x, const LayerSurfaceOptions& options = {});

}  // namespace granwave
