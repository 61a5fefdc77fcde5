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
  // What the closures see (GranularHydro1D::cellView), inverted for the node spacing.
  const double theta_eff = pde.effectiveTemperature(theta);
  const double rho_max = m.packingLimit() * m.mass / m.diskArea();
  auto pressure = [&](double rho_eff) { return m.pressure(rho_eff, theta_eff); };

  std::vector<double> U(pde.size(), 0.0);
  const double weight = N * m_c * g.gravity;
  // On a hard wall the layer rests at the plate; on the spring where it carries the weight.
  const double gap =
      pde.hardWalls()
          ? 0.0
          : solveIncreasing([&](double z) { return -pde.contactStress(z, 0.0, 0.0, 0.0); }, -weight,
                            1e-9 * m.sigma, pde.regularisation().wall_contact_range * m.sigma);
  double z = gap;
  for (int i = 0; i < N; ++i) {
    const double stress = (N - i - 0.5) * m_c * g.gravity;
    const double rho_eff =
        solveIncreasing(pressure, stress, 1e-12 * rho_max, rho_max * (1 - 1e-15));
    U[pde.heightIndex(i)] = z;
    U[pde.temperatureIndex(i)] = pde.temperatureUnknown(theta);
    if (pde.rough()) U[pde.rotationIndex(i)] = pde.temperatureUnknown(theta);  // equipartition
    z += pde.spacingFor(rho_eff);
  }
  U[pde.heightIndex(N)] = z;
  if (z > g.height)
    throw std::invalid_argument("the settled layer (" + std::to_string(z) +
                                " m) does not fit under the lid (" + std::to_string(g.height) +
                                " m)");
  return U;
}

std::vector<double> spreadLayer(const GranularHydro1D& pde, double theta) {
  const HydroGeometry& g = pde.geometry();
  const double sigma = pde.model().sigma;
  // Out of reach of both wall contacts, so the layer starts free; with hard walls (no reach)
  // 0.1 d, the spring's default reach, so that both start from the same layer.
  const double gap =
      pde.hardWalls() ? 0.1 * sigma : 2 * pde.regularisation().wall_contact_range * sigma;
  const double spacing = (g.height - 2 * gap) / g.cells;
  if (pde.cellMass() / spacing >=
      pde.model().packingLimit() * pde.model().mass / pde.model().diskArea())
    throw std::invalid_argument(
        "the layer spread over the container would be packed past close packing");
  std::vector<double> U(pde.size(), 0.0);
  for (int j = 0; j <= g.cells; ++j) {
    U[pde.heightIndex(j)] = gap + j * spacing;
    if (j == g.cells) break;
    U[pde.temperatureIndex(j)] = pde.temperatureUnknown(theta);
    if (pde.rough()) U[pde.rotationIndex(j)] = pde.temperatureUnknown(theta);
  }
  return U;
}

}  // namespace granwave::hydro
