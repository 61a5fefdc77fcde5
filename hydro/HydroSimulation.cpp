#include "hydro/HydroSimulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace granwave::hydro {

HydroSimulation::HydroSimulation(const GranularHydro1D& pde, int particles, double width,
                                 const HydroRunOptions& o)
    : pde_(pde), column_mass_(particles * pde.model().mass / width), opt_(o) {}

std::vector<double> HydroSimulation::initialState() const {
  const int N = pde_.geometry().cells;
  const double h = pde_.dz();
  const double m = pde_.model().mass, sigma = pde_.model().sigma;
  const double disk = std::numbers::pi * sigma * sigma / 4;
  const double rho_layer = opt_.initial_area_fraction * m / disk;
  const double top = column_mass_ / rho_layer;  // layer height
  std::vector<double> U(static_cast<std::size_t>(GranularHydro1D::kVars) * N);
  double total = 0;
  for (int i = 0; i < N; ++i) {
    // Smooth upper edge over one diameter; a tiny gas everywhere keeps every cell defined.
    const double z = pde_.cellCentre(i);
    const double shape = 0.5 * (1 - std::tanh((z - top) / (0.5 * sigma)));
    U[3 * i] = rho_layer * shape + 1e-6 * rho_layer;
    total += U[3 * i] * h;
  }
  const double scale = column_mass_ / total;
  for (int i = 0; i < N; ++i) {
    U[3 * i] *= scale;
    U[3 * i + 1] = 0;
    U[3 * i + 2] = U[3 * i] * opt_.initial_theta;
  }
  return U;
}

HydroPhase HydroSimulation::snapshot(double t, const std::vector<double>& U) const {
  const int N = pde_.geometry().cells;
  const double m = pde_.model().mass, sigma = pde_.model().sigma;
  const double disk = std::numbers::pi * sigma * sigma / 4;
  HydroPhase p;
  p.time = t;
  p.plate_height = pde_.geometry().amplitude * std::sin(pde_.geometry().omega * t);
  double mz = 0, mm = 0;
  for (int i = 0; i < N; ++i) {
    const double rho = std::max(U[3 * i], 0.0);
    const double u = rho > pde_.rhoFloor() ? U[3 * i + 1] / rho : 0.0;
    const double theta =
        rho > pde_.rhoFloor() ? std::max(U[3 * i + 2] / rho - 0.5 * u * u, 0.0) : 0.0;
    p.n.push_back(rho / m);
    p.u.push_back(u);
    p.theta.push_back(theta);
    p.area_fraction.push_back(rho / m * disk);
    p.pressure.push_back(
        pde_.model().pressure(std::max(rho, pde_.rhoFloor()), std::max(theta, pde_.thetaFloor())));
    mz += rho * pde_.cellCentre(i);
    mm += rho;
  }
  p.center_of_mass_height = mm > 0 ? mz / mm : 0;
  return p;
}

HydroResult HydroSimulation::run() {
  const auto wall0 = std::chrono::steady_clock::now();
  const HydroGeometry& g = pde_.geometry();
  const int N = g.cells, M = opt_.samples_per_cycle;
  const double T = 2 * std::numbers::pi / g.omega;
  const double sigma = pde_.model().sigma;
  // Close-packed mass density (hexagonal packing of disks), kg/m^2.
  const double rho_cp = pde_.model().mass / (std::numbers::pi * sigma * sigma / 4) *
                        (std::numbers::pi / (2 * std::sqrt(3.0)));
  CvodeOptions co = opt_.cvode;
  if (co.atol.empty()) {
    // Per-variable noise levels (physics-hydro.md 5.3): 1e-8 of close packing, times
    // sqrt(g sigma) and g sigma for momentum and energy.
    const double v = std::sqrt(g.gravity * sigma);
    const double a = opt_.atol_scale;
    co.atol.resize(3 * N);
    for (int i = 0; i < N; ++i) {
      co.atol[3 * i] = a * rho_cp;
      co.atol[3 * i + 1] = a * rho_cp * v;
      co.atol[3 * i + 2] = a * rho_cp * v * v;
    }
  }
  if (co.band_upper == 0) co.band_upper = co.band_lower = GranularHydro1D::kHalfBand;
  if (co.constraints.empty() && opt_.positivity) {
    // rho > 0 and E > 0 (CVODE semantics 2.0), momentum free (physics-hydro.md 5.4).
    co.constraints.assign(3 * N, 2.0);
    for (int i = 0; i < N; ++i) co.constraints[3 * i + 1] = 0.0;
  }
  if (co.max_step == 0) co.max_step = T / (2 * M);

  std::vector<double> U = initialState();
  HydroResult r;
  for (int i = 0; i < N; ++i) r.initial_mass += U[3 * i] * pde_.dz();
  CvodeIntegrator cv(
      [this](double t, const double* y, double* yd) { return pde_.rightHandSide(t, y, yd); }, 0.0,
      U, co, [this](int k) { return pde_.componentName(k); });

  std::vector<HydroPhase> recent;  // last 2 cycles of phases
  for (int cycle = 0; cycle < opt_.max_cycles; ++cycle) {
    for (int k = 1; k <= M; ++k) {
      const double t = (cycle + static_cast<double>(k) / M) * T;
      cv.advanceTo(t);
      HydroPhase ph = snapshot(t, cv.state());
      r.com_per_phase.push_back(ph.center_of_mass_height);
      recent.push_back(std::move(ph));
      if (static_cast<int>(recent.size()) > 2 * M) recent.erase(recent.begin());
    }
    r.cycles = cycle + 1;
    if (r.cycles < opt_.min_cycles) continue;
    // Compare the last cycle with the one P cycles before, relative to its amplitude.
    const auto& h = r.com_per_phase;
    const std::size_t end = h.size();
    const auto [lo, hi] = std::minmax_element(h.end() - M, h.end());
    const double amp = std::max(*hi - *lo, 1e-12);
    for (int P = 1; P <= 2 && !r.periodic; ++P) {
      double worst = 0;
      for (int k = 0; k < M; ++k)
        worst = std::max(
            worst, std::abs(h[end - 1 - k] - h[end - 1 - k - static_cast<std::size_t>(P) * M]));
      if (worst <= opt_.periodic_tolerance * amp) {
        r.periodic = true;
        r.period = P;
      }
    }
    if (r.periodic) break;
  }
  const int P = r.periodic ? r.period : 2;
  r.window.assign(recent.end() - static_cast<long>(P) * M, recent.end());
  r.stats = cv.stats();
  for (int i = 0; i < N; ++i) r.final_mass += cv.state()[3 * i] * pde_.dz();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return r;
}

}  // namespace granwave::hydro
