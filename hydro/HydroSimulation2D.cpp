#include "hydro/HydroSimulation2D.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <numbers>
#include <string>

#include "hydro/ColumnPreconditioner.hpp"
#include "hydro/Layer2DRemap.hpp"
#include "hydro/Layer2DStart.hpp"

namespace granwave::hydro {

namespace {

double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

HydroSimulation2D::HydroSimulation2D(const GranularHydro2D& op, const Hydro2DRunOptions& o)
    : op_(op), opt_(o) {}

std::vector<double> HydroSimulation2D::initialState() const {
  const double theta = opt_.initial_theta > 0 ? opt_.initial_theta
                                              : 1e-3 * op_.geometry().gravity * op_.model().sigma;
  return columnStart(op_, theta, opt_.spread);
}

CvodeOptions HydroSimulation2D::solverOptions() const {
  const double sigma = op_.model().sigma, a = opt_.atol_scale;
  const double v = std::sqrt(op_.geometry().gravity * sigma);
  double mean_mass = 0;
  for (double m : op_.initialCellMass()) mean_mass += m / op_.initialCellMass().size();
  CvodeOptions co;
  co.method = CvodeMethod::BdfKrylov;
  co.rtol = opt_.rtol;
  co.atol.assign(op_.size(), 1e30);  // the budget's quadratures take no part in the error test
  for (int i = 0; i < op_.columns(); ++i)
    for (int j = 0; j <= op_.cells(); ++j) {
      co.atol[op_.heightIndex(i, j)] = 100 * a * sigma;
      co.atol[op_.velocityIndex(i, j)] = 100 * a * v;
      if (j == op_.cells()) break;
      co.atol[op_.temperatureIndex(i, j)] = 1e4 * a;
      co.atol[op_.fluxIndex(i, j)] = 100 * a * mean_mass * op_.dx();
      co.atol[op_.horizontalVelocityIndex(i, j)] = 100 * a * v;
      if (op_.rough()) co.atol[op_.rotationIndex(i, j)] = 1e4 * a;
    }
  const double T = 2 * std::numbers::pi / op_.geometry().omega;
  co.max_step = T / (2 * opt_.samples_per_cycle);
  co.max_steps = opt_.max_steps_per_cycle;
  co.krylov_dimension = opt_.krylov_dimension;
  return co;
}

Hydro2DPhase HydroSimulation2D::snapshot(double t, const std::vector<double>& U) const {
  const ConstitutiveModel& m = op_.model();
  const int Nx = op_.columns(), N = op_.cells();
  Hydro2DPhase p;
  p.time = t;
  p.plate_height = op_.geometry().plateHeight(t);
  p.plate_velocity = op_.geometry().plateVelocity(t);
  double mz = 0, mass = 0;
  for (int i = 0; i < Nx; ++i) {
    for (int j = 0; j <= N; ++j) p.node_z.push_back(U[op_.heightIndex(i, j)]);
    const int l = i > 0 ? i - 1 : (op_.periodic() ? Nx - 1 : -1);
    for (int k = 0; k < N; ++k) {
      const GranularHydro2D::CellView c = op_.cellView(U.data(), i, k);
      const double rho = c.mass / c.length;
      const double uL = l < 0 ? 0.0 : U[op_.horizontalVelocityIndex(l, k)];
      const double uR = op_.wallFace(i) ? 0.0 : U[op_.horizontalVelocityIndex(i, k)];
      p.area_fraction.push_back(m.areaFraction(rho));
      p.theta.push_back(op_.temperatureOf(U[op_.temperatureIndex(i, k)]));
      p.velocity_x.push_back(0.5 * (uL + uR));
      p.velocity_z.push_back(0.5 * (U[op_.velocityIndex(i, k)] + U[op_.velocityIndex(i, k + 1)]));
      p.pressure.push_back(m.pressure(c.rho, c.theta));
      p.mass.push_back(op_.cellMass(U.data(), i, k) * op_.dx());
      if (op_.rough()) p.rotation.push_back(op_.temperatureOf(U[op_.rotationIndex(i, k)]));
      mz += p.mass.back() * c.centre;
      mass += p.mass.back();
    }
  }
  p.center_of_mass_height = mz / mass;
  return p;
}

Hydro2DResult HydroSimulation2D::run(const Hydro2DObserver& observe) {
  const double cpu0 = threadCpuSeconds();
  const int M = opt_.samples_per_cycle;
  const double T = 2 * std::numbers::pi / op_.geometry().omega;
  ColumnPreconditioner pre(op_);
  CvodeOptions co = solverOptions();
  co.preconditioner = pre.callbacks();
  Hydro2DResult r;
  if (opt_.remap_share > 0) {
    co.events = 1;
    co.event_functions = [this](double, const double* y, double* g) {
      g[0] = thinnestLayerShare(op_, y) - opt_.remap_share;
    };
    co.on_event = [this, &r, T](double t, std::vector<double>& y, const std::vector<int>&) {
      try {
        r.remap_heat += remapLayers(op_, t, y);
      } catch (const std::runtime_error& e) {  // a column emptied, or too much energy to move
        const int cycle = static_cast<int>(std::floor(t / T)) + 1;
        throw HydroFailure(std::string(e.what()) + " (cycle " + std::to_string(cycle) + ")", t,
                           cycle);
      }
      ++r.remaps;
    };
  }
  CvodeIntegrator cv(
      [this](double t, const double* y, double* yd) { return op_.rightHandSide(t, y, yd); }, 0.0,
      initialState(), co, [this](int k) { return op_.componentName(k); });
  const double mass0 = op_.totalMass();
  long steps_before = 0;
  const std::size_t keep = static_cast<std::size_t>(std::max(1, opt_.window_cycles)) * M;
  for (int cycle = 0; cycle < opt_.cycles; ++cycle) {
    for (int k = 1; k <= M; ++k) {
      const double t = (cycle + static_cast<double>(k) / M) * T;
      PhaseBudget budget;
      try {
        budget = advanceWithBudget(op_, cv, t);
      } catch (const CvodeError& e) {
        throw HydroFailure(std::string(e.what()) + " (cycle " + std::to_string(cycle + 1) + ")",
                           e.time(), cycle + 1);
      }
      Hydro2DPhase ph = snapshot(t, cv.state());
      ph.budget = budget;
      double mass = 0;
      for (double m : ph.mass) mass += m;
      r.mass_drift = std::max(r.mass_drift, std::abs(mass / mass0 - 1));
      r.com_per_phase.push_back(ph.center_of_mass_height);
      if (observe) observe(ph, cycle, k - 1);
      if (cycle >= opt_.cycles - opt_.window_cycles) r.window.push_back(std::move(ph));
      if (r.window.size() > keep) r.window.erase(r.window.begin());
    }
    const long steps = cv.stats().steps;
    r.steps_per_cycle.push_back(steps - steps_before);
    steps_before = steps;
    r.cycles = cycle + 1;
    if (r.steps_per_cycle.back() > opt_.max_steps_per_cycle)
      throw HydroFailure("no progress: cycle " + std::to_string(r.cycles) + " needed " +
                             std::to_string(r.steps_per_cycle.back()) + " steps (budget " +
                             std::to_string(opt_.max_steps_per_cycle) + ")",
                         cv.time(), r.cycles);
  }
  r.stats = cv.stats();
  r.preconditioner_jacobians = pre.jacobianEvaluations();
  r.cpu_seconds = threadCpuSeconds() - cpu0;
  return r;
}

}  // namespace granwave::hydro
