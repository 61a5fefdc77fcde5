#pragma once
// Shared by the 2D operator's tests: the paper's beads in columns, and states away from
// equilibrium in every variable (a wet layer in flight, compressed near the plate and dilute on
// top, hot and cold cells), flat or varying between columns.
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "HydroTestSupport.hpp"
#include "hydro/GranularHydro2D.hpp"

namespace granwave::hydro::test {

// The paper's beads with the wet restitution law (e_inf 0.91, St_c/q 0.0698 m/s), smooth or rough.
inline ConstitutiveModel wetModel(bool rough) {
  ConstitutiveModel m =
      beadModel(RestitutionClosure::wet(0.91, 0.0698), RestitutionClosure::wet(0.91, 0.0698));
  m.rough.enabled = rough;
  return m;
}

// The paper's box and drive at full amplitude from t = 0 (no ramp).
inline HydroGeometry drivenBox(int cells) {
  HydroGeometry g = paperGeometry(cells);
  g.ramp_time = 0;
  return g;
}

// A 1D column state away from equilibrium (the JacobianTest's): node heights for the column
// mass per unit width M, random velocities and temperatures from the seed.
inline std::vector<double> rumpledColumn(const GranularHydro1D& pde, unsigned seed) {
  const int N = pde.cells();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U01(0, 1);
  std::vector<double> U(pde.size(), 0.0);
  double z = 0.02 * kD;  // the bottom node inside the plate's contact range
  for (int j = 0; j <= N; ++j) {
    U[pde.heightIndex(j)] = z;
    U[pde.velocityIndex(j)] = 0.5 * (U01(rng) - 0.5);
    if (j == N) break;
    const double nu = j < N / 4 ? 0.6 + 0.25 * U01(rng) : 0.02 + 0.5 * U01(rng);
    U[pde.temperatureIndex(j)] = pde.temperatureUnknown(0.05 * (0.01 + U01(rng)));
    if (pde.rough()) U[pde.rotationIndex(j)] = pde.temperatureUnknown(0.03 * (0.01 + U01(rng)));
    z += pde.cellMass() / densityOf(nu);
  }
  return U;
}

// Copies a 1D column state into column i of a 2D state.
inline void putColumn(const GranularHydro2D& op, const GranularHydro1D& pde,
                      const std::vector<double>& V, int i, std::vector<double>& U) {
  for (int j = 0; j <= op.cells(); ++j) {
    U[op.heightIndex(i, j)] = V[pde.heightIndex(j)];
    U[op.velocityIndex(i, j)] = V[pde.velocityIndex(j)];
    if (j == op.cells()) break;
    U[op.temperatureIndex(i, j)] = V[pde.temperatureIndex(j)];
    if (op.rough()) U[op.rotationIndex(i, j)] = V[pde.rotationIndex(j)];
  }
}

// A 2D state whose columns differ (their own rumpled columns, shifted heights) with random
// mass fluxes (within a tenth of a cell's mass) and horizontal velocities.
inline std::vector<double> rumpledLayer(const GranularHydro2D& op, const GranularHydro1D& pde,
                                        unsigned seed) {
  std::vector<double> U(op.size(), 0.0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U01(0, 1);
  for (int i = 0; i < op.columns(); ++i) {
    std::vector<double> V = rumpledColumn(pde, seed + 17 * i);
    const double lift = 0.3 * kD * U01(rng);
    for (int j = 0; j <= op.cells(); ++j) V[pde.heightIndex(j)] += j == 0 ? 0.0 : lift;
    putColumn(op, pde, V, i, U);
    for (int k = 0; k < op.cells(); ++k) {
      if (op.wallFace(i)) continue;
      U[op.fluxIndex(i, k)] = 0.1 * pde.cellMass() * op.dx() * (U01(rng) - 0.5);
      U[op.horizontalVelocityIndex(i, k)] = 0.4 * (U01(rng) - 0.5);
    }
  }
  return U;
}

}  // namespace granwave::hydro::test
