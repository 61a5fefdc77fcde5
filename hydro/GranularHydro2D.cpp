#include "hydro/GranularHydro2D.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "hydro/Layer2DResidual.hpp"

namespace granwave::hydro {

GranularHydro2D::GranularHydro2D(const HydroGeometry& g, const HydroColumns& x,
                                 const ConstitutiveModel& model, std::vector<double> cell_mass,
                                 const HydroRegularisation& numerics, bool energy_budget)
    : g_(g),
      x_(x),
      model_(model),
      numerics_(numerics),
      mu0_(std::move(cell_mass)),
      vars_(model.rough.enabled ? 6 : 5),
      theta_unit_(std::max(g.gravity, 1.0) * model.sigma),
      energy_budget_(energy_budget) {
  if (x.columns < 1 || g.cells < 1 || !(x.width > 0))
    throw std::invalid_argument("the 2D continuum needs at least one column and one cell");
  if (mu0_.size() != static_cast<std::size_t>(x.columns) * g.cells)
    throw std::invalid_argument("the 2D continuum needs one mass per cell");
  model_.side_wall_width = 0;  // side walls are explicit here, not a sink
  const double unit = std::max(g.gravity, 1.0) * model.sigma;
  reg_ = {model.packingLimit() * model.mass / model.diskArea(),
          numerics.packing_width * model.mass / model.diskArea(),
          1e-6 * model.sigma,
          numerics.temperature_floor * unit,
          1e-4 * std::sqrt(unit),
          kHexagonalClosePacking * model.mass / model.diskArea() * unit};
  // 1e-9 of the mean cell mass: the closures see mu + floor^2/(4 mu) for mu >> floor.
  mass_floor_ = 1e-9 * std::accumulate(mu0_.begin(), mu0_.end(), 0.0) / mu0_.size();
  values_ = std::make_unique<Workspace<double>>(x.columns, g.cells, x.periodic);
}

GranularHydro2D::~GranularHydro2D() = default;

double GranularHydro2D::totalMass() const {
  return dx() * std::accumulate(mu0_.begin(), mu0_.end(), 0.0);
}

double GranularHydro2D::temperatureUnknown(double theta) const {
  return std::log(theta / theta_unit_);
}
double GranularHydro2D::temperatureOf(double s) const { return theta_unit_ * std::exp(s); }

double GranularHydro2D::cellMass(const double* U, int i, int k) const {
  const int l = i > 0 ? i - 1 : (x_.periodic ? x_.columns - 1 : -1);
  const double left = l < 0 ? 0.0 : U[fluxIndex(l, k)];
  const double right = wallFace(i) ? 0.0 : U[fluxIndex(i, k)];
  return mu0_[static_cast<std::size_t>(i) * g_.cells + k] + (left - right) / dx();
}

GranularHydro2D::CellView GranularHydro2D::cellView(const double* U, int i, int k) const {
  const double mass = smoothPositivePart(cellMass(U, i, k), mass_floor_);
  const double z0 = U[heightIndex(i, k)], z1 = U[heightIndex(i, k + 1)];
  const EffectiveCell<double> e =
      effectiveCell(reg_, mass, theta_unit_, z0, z1, U[temperatureIndex(i, k)]);
  return {e.rho, e.theta, e.length, mass, 0.5 * (z0 + z1)};
}

std::string GranularHydro2D::componentName(int k) const {
  if (k >= layerSize()) return "energy budget " + std::to_string(k - layerSize());
  const int i = k / columnSize(), r = k % columnSize(), j = r / vars_;
  const std::string at = "column " + std::to_string(i) + ", ";
  static const char* names[] = {"height",    "vertical velocity",   "temperature",
                                "mass flux", "horizontal velocity", "rotational temperature"};
  return at + (r % vars_ < 2 ? "node " : "cell ") + std::to_string(j) + ", " + names[r % vars_];
}

int GranularHydro2D::rightHandSide(double t, const double* U, double* dUdt) const {
  const int status = residual(t, U, dUdt, *values_);
  if (status != 0 || !energy_budget_) return status;
  const EnergyRates r = ratesOf(t, *values_);
  const double rates[kBudgetTerms] = {r.plate_work, r.collisional_loss, r.friction_loss,
                                      r.wall_loss, r.side_wall_loss};
  for (int k = 0; k < kBudgetTerms; ++k) dUdt[budgetIndex(k)] = rates[k];
  return 0;
}

GranularHydro2D::EnergyRates GranularHydro2D::energyRates(double t, const double* U) const {
  std::vector<double> dU(size());
  residual(t, U, dU.data(), *values_);
  return ratesOf(t, *values_);
}

GranularHydro2D::EnergyRates GranularHydro2D::ratesOf(double t, const Workspace<double>& w) const {
  EnergyRates r;
  const double vb = g_.plateVelocity(t);
  for (int i = 0; i < x_.columns; ++i) {
    const auto& wall = w.walls[i];
    r.plate_work += dx() * (wall.plate_stress - wall.lid_stress) * vb;
    r.wall_loss += dx() * (wall.plate_loss + wall.lid_loss);
    r.contact_drift += dx() * (wall.plate_elastic * w.drift[w.grid.node(i, 0)] -
                               wall.lid_elastic * w.drift[w.grid.node(i, g_.cells)]);
  }
  for (std::size_t c = 0; c < w.local.size(); ++c) {
    r.collisional_loss += w.local[c].cooling * dx() * w.len[c];
    if (rough()) r.friction_loss -= dx() * w.mass[c] * (w.exchange[c] + 0.5 * w.spin[c]);
  }
  r.side_wall_loss = w.side_loss;
  return r;
}

double GranularHydro2D::labEnergy(double t, const double* U) const {
  Workspace<double>& w = *values_;
  std::vector<double> dU(size());
  residual(t, U, dU.data(), w);
  const ColumnGrid& grid = w.grid;
  const double zb = g_.plateHeight(t), vb = g_.plateVelocity(t), h = dx();
  double E = 0;
  for (int i = 0; i < x_.columns; ++i) {
    for (int j = 0; j <= g_.cells; ++j) {
      double m = 0;
      if (j > 0) m += 0.5 * h * w.mass[grid.cell(i, j - 1)];
      if (j < g_.cells) m += 0.5 * h * w.mass[grid.cell(i, j)];
      const double v = U[velocityIndex(i, j)] + vb;
      E += 0.5 * m * v * v + m * g_.gravity * (U[heightIndex(i, j)] + zb);
    }
    for (int k = 0; k < g_.cells; ++k) {
      const int c = grid.cell(i, k);
      const double m = h * w.mass[c];
      E += m * temperatureOf(U[temperatureIndex(i, k)]);
      if (rough()) E += 0.5 * m * temperatureOf(U[rotationIndex(i, k)]);
      if (wallFace(i)) continue;
      const double u = U[horizontalVelocityIndex(i, k)];
      E += 0.25 * h * (w.mass[c] + w.mass[grid.cell(grid.right(i), k)]) * u * u;
    }
    E += h * (wallContactEnergy(U[heightIndex(i, 0)], model_.sigma, reg_.contact_scale, numerics_) +
              wallContactEnergy(g_.height - U[heightIndex(i, g_.cells)], model_.sigma,
                                reg_.contact_scale, numerics_));
  }
  return E;
}

template int GranularHydro2D::residual<double>(double, const double*, double*,
                                               Workspace<double>&) const;

}  // namespace granwave::hydro
