#include "hydro/SettledLayer.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace granwave::hydro {

namespace {

// Solves f(x) = target for x in (lo, hi), f increasing, by bisection to double precision.
template <class F>
double solveIncreasing(const F& f, double target, double lo, double hi) {
  for (int k = 0; k < 200 && hi - lo > 1e-15 * std::abs(hi); ++k) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

std::vector<double> settledLayer(const GranularHydro1D& pde, double theta) {
  const ConstitutiveModel& m = pde.model();
  const HydroGeometry& g = pde.geometry();
  const int N = g.cells;
  const double m_c = pde.cellMass();
  // The operator's floors (GranularHydro1D.cpp, cellStates): the temperature it sees, and the
  // packing map rho_eff(rho) = rho_max - d s((rho_max - rho)/d), inverted below.
  const double theta_min = 1e-8 * g.gravity * m.sigma;
  const double x = theta - theta_min;
  const double theta_eff = theta_min + 0.5 * (x + std::sqrt(x * x + theta_min * theta_min));
  const double rho_max = m.packingLimit() * m.mass / m.diskArea();
  const double d = 1e-4 * m.mass / m.diskArea();
  auto pressure = [&](double rho_eff) { return m.pressure(rho_eff, theta_eff); };

  std::vector<double> U(pde.size(), 0.0);
  const double weight = N * m_c * g.gravity;
  const double gap =
      solveIncreasing([&](double z) { return -pde.contactStress(z, 0.0, 0.0, 0.0); }, -weight,
                      1e-9 * m.sigma, GranularHydro1D::kContactRange * m.sigma);
  double z = gap;
  for (int i = 0; i < N; ++i) {
    const double stress = (N - i - 0.5) * m_c * g.gravity;
    const double rho_eff =
        solveIncreasing(pressure, stress, 1e-12 * rho_max, rho_max * (1 - 1e-15));
    const double y = (rho_max - rho_eff) / d;  // s((rho_max - rho)/d) = y
    const double rho = rho_max - d * (y - 1 / y);
    U[GranularHydro1D::heightIndex(i)] = z;
    U[GranularHydro1D::temperatureIndex(i)] = theta;
    z += m_c / rho;
  }
  U[GranularHydro1D::heightIndex(N)] = z;
  if (z > g.height)
    throw std::invalid_argument("the settled layer (" + std::to_string(z) +
                                " m) does not fit under the lid (" + std::to_string(g.height) +
                                " m)");
  return U;
}

}  // namespace granwave::hydro
