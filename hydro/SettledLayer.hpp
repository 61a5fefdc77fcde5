#pragma once
// The initial state of a run: the layer settled on the plate, at rest, at a small uniform
// temperature, in the exact discrete hydrostatic balance of the Lagrangian operator: with the
// top free, cell i carries the weight of the cells above it and half its own,
//   Pi_i = (N - i - 1/2) m_c g,
// the plate's contact carries the whole layer, M g, and each cell's density solves
// p(rho_i, theta) = Pi_i through the same closures (and the same floors) as the operator.
// Throws std::invalid_argument if the settled layer does not fit under the lid.
#include <vector>

#include "hydro/GranularHydro1D.hpp"

namespace granwave::hydro {

// theta in m^2/s^2; returns the state vector of GranularHydro1D.
std::vector<double> settledLayer(const GranularHydro1D& pde, double theta);

// The grains spread evenly over the container at rest, as the particle engine places them
// (initial.placement = "random": uniform in height from the plate to the lid): the cells of
// equal mass evenly spaced between the plate and the lid, at rest, at temperature theta. The
// layer then falls onto the plate and its landing shock heats it, as the particles' does.
std::vector<double> spreadLayer(const GranularHydro1D& pde, double theta);

}  // namespace granwave::hydro
