#pragma once
// The surface of the 2D continuum's layer, measured as the particles' is (coarse_grain/
// LayerSurface.hpp, layerSurfaceOfField): its area fraction on the surface's columns (one
// diameter wide) and z bins, each bin the mean over its area of the continuum's cells (a
// finite-volume cell's value is its average over its column's width and between its node
// heights), then blurred by the particles' kernel and crossed at half the bulk value. So the
// continuum's and the particles' surface spectra (coarse_grain/SurfaceWaveSpectrum.hpp) are one
// measure on two models (docs/hydro.md, "The 2D model").
#include "coarse_grain/LayerSurface.hpp"
#include "hydro/HydroSimulation2D.hpp"

namespace granwave {

struct ContinuumColumns {
  int columns = 0, cells = 0;  // the continuum's Nx and N per column
  double width = 0;            // m
  bool periodic_x = true;
  double diameter = 0;  // m
};

// The area fraction of one recorded phase on the surface's grid: round(width / diameter)
// columns, bins of options.z_bin d from the plate to 3 kernel widths above the highest node.
AreaFractionGrid continuumAreaFraction(const hydro::Hydro2DPhase& phase, const ContinuumColumns& c,
                                       const LayerSurfaceOptions& options = {});

// The phase's surface by the particles' rule.
LayerSurface continuumSurface(const hydro::Hydro2DPhase& phase, const ContinuumColumns& c,
                              const LayerSurfaceOptions& options = {});

}  // namespace granwave
