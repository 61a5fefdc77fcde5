#pragma once
// The starting states of GranularHydro2D: every column as GranularHydro1D starts a layer of its
// mass (hydro/SettledLayer.hpp: settled on the plate, or spread over the container as the
// particle engine places its grains), at rest, and the seeded perturbation that lets the
// layer choose its own surface waves: the columns' masses
//
//   M_i = M (1 + a xi_i),   xi_i white noise of zero mean and unit RMS over the columns,
//
// drawn from a Mersenne twister (std::mt19937_64) seeded by the scene's seed, so the same seed
// gives the same layer. a = 0 is the flat layer, which stays flat (each column is the 1D
// operator exactly).
#include <cstdint>
#include <vector>

#include "hydro/GranularHydro2D.hpp"

namespace granwave::hydro {

// mu0 of every cell ([i N + k], kg/m): column_mass (kg/m, the layer's mass per unit width)
// perturbed as above and shared equally by the column's N cells (draws beyond 3 standard
// deviations are drawn again, so a <= 0.1 leaves every column more than half its mass).
std::vector<double> perturbedCellMasses(int columns, int cells, double column_mass,
                                        double amplitude, std::uint64_t seed);

// The state with every column settled (spread = false) or spread (true) at temperature theta
// (m^2/s^2), horizontal velocities and mass fluxes zero. Throws std::invalid_argument as
// settledLayer and spreadLayer do, or if a column's cells differ in mass.
std::vector<double> columnStart(const GranularHydro2D& op, double theta, bool spread);

}  // namespace granwave::hydro
