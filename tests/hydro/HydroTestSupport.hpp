#pragma once
// Shared by the hydro tests: the paper's glass beads, a constitutive model built from a pair
// and a wall restitution law (Knudsen limiter at one diameter, no elastic contact pressure, as
// `granwave hydro` by default), and uniform or settled states of the Lagrangian operator.
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "hydro/ConstitutiveModel.hpp"
#include "hydro/CvodeIntegrator.hpp"
#include "hydro/GranularHydro1D.hpp"

namespace granwave::hydro::test {

inline constexpr double kD = 0.002;  // m, particle diameter
inline const double kMass = 2580 * std::numbers::pi * kD * kD * kD / 6;
inline const double kDisk = std::numbers::pi * kD * kD / 4;  // disk area, m^2
inline const double kRhoCp = kHexagonalClosePacking * kMass / kDisk;

inline ConstitutiveModel beadModel(RestitutionClosure pairs, RestitutionClosure walls) {
  ConstitutiveModel m;
  m.mass = kMass;
  m.sigma = kD;
  m.restitution = pairs;
  m.wall_restitution = walls;
  m.knudsen_length = kD;
  return m;
}

// The paper's container and drive: a 30 d tall box shaken at 10 Hz and Gamma = 4, the drive
// ramped up over its first 0.2 s, in `cells` cells.
inline HydroGeometry paperGeometry(int cells) {
  HydroGeometry g;
  g.cells = cells;
  g.height = 30 * kD;
  g.omega = 2 * std::numbers::pi * 10;
  g.amplitude = 4 * 9.81 / (g.omega * g.omega);
  g.ramp_time = 0.2;
  return g;
}

inline double densityOf(double nu) { return nu * kMass / kDisk; }

// A gas at rest at area fraction nu and temperature theta filling a closed box of `cells`
// cells and height L with gravity g: the operator and its state, with both boundary nodes
// where their wall contact balances the gas pressure (in the limit g -> 0 that is uniform).
struct Column {
  std::unique_ptr<GranularHydro1D> pde;
  std::vector<double> U;
};

inline Column uniformGas(const ConstitutiveModel& m, int cells, double height, double nu,
                         double theta, double gravity = 0) {
  HydroGeometry g;
  g.cells = cells;
  g.height = height;
  g.gravity = gravity;
  const double mass = densityOf(nu) * height;
  Column c{std::make_unique<GranularHydro1D>(g, m, mass), {}};
  const GranularHydro1D& pde = *c.pde;
  c.U.assign(pde.size(), 0.0);
  auto place = [&](double gap) {
    const double length = (height - 2 * gap) / cells;
    for (int j = 0; j <= cells; ++j) {
      c.U[c.pde->heightIndex(j)] = gap + j * length;
      if (j < cells) c.U[c.pde->temperatureIndex(j)] = c.pde->temperatureUnknown(theta);
      if (j < cells && c.pde->rough())
        c.U[c.pde->rotationIndex(j)] = c.pde->temperatureUnknown(theta);
    }
  };
  double gap = 0;
  for (int k = 0; k < 60; ++k) {  // fixed point: the gap sets the density, which sets the gap
    place(gap);
    const GranularHydro1D::CellView v = pde.cellView(c.U.data(), 0);  // as the closures see it
    const double p = m.pressure(v.rho, v.theta);
    double lo = 0, hi = pde.regularisation().wall_contact_range * kD;
    for (int b = 0; b < 200; ++b) {
      const double mid = 0.5 * (lo + hi);
      (pde.contactStress(mid, 0, 0, 0) > p ? lo : hi) = mid;
    }
    gap = 0.5 * (lo + hi);
  }
  place(gap);
  return c;
}

inline CvodeIntegrator integrator(const GranularHydro1D& pde, const std::vector<double>& U,
                                  double rtol) {
  CvodeOptions o;
  o.rtol = rtol;
  o.atol.assign(U.size(), 0.0);
  for (int j = 0; j <= pde.cells(); ++j) {
    o.atol[pde.heightIndex(j)] = 1e-12;
    o.atol[pde.velocityIndex(j)] = 1e-12;
    if (j < pde.cells()) o.atol[pde.temperatureIndex(j)] = 1e-10;  // ln theta: relative
    if (j < pde.cells() && pde.rough()) o.atol[pde.rotationIndex(j)] = 1e-10;
  }
  o.band_upper = o.band_lower = pde.halfBand();
  o.max_steps = 200000;
  o.jacobian = [&pde](double t, const double* y, const BandMatrixWriter& w) {
    return pde.jacobian(t, y, w);
  };
  return CvodeIntegrator(
      [&pde](double t, const double* y, double* d) { return pde.rightHandSide(t, y, d); }, 0.0, U,
      o);
}

// Density and temperature of cell i of a state.
inline double cellDensity(const GranularHydro1D& pde, const std::vector<double>& U, int i) {
  return pde.cellMass() / (U[pde.heightIndex(i + 1)] - U[pde.heightIndex(i)]);
}
inline double cellCentre(const GranularHydro1D& pde, const std::vector<double>& U, int i) {
  return 0.5 * (U[pde.heightIndex(i)] + U[pde.heightIndex(i + 1)]);
}

}  // namespace granwave::hydro::test
