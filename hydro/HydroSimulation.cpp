#include "hydro/HydroSimulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <ctime>
#include <numbers>

#include "hydro/SettledLayer.hpp"

namespace granwave::hydro {

namespace {

double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

std::string regimeName(HydroRegime r) {
  switch (r) {
    case HydroRegime::Fluidised:
      return "fluidised";
    case HydroRegime::Solid:
      return "no fluidised region: the layer moves as a solid";
    case HydroRegime::AtRest:
      return "the layer rests on the plate";
  }
  return "unknown";
}

HydroSimulation::HydroSimulation(const GranularHydro1D& pde, const HydroRunOptions& o)
    : pde_(pde), opt_(o) {}

std::vector<double> HydroSimulation::initialState() const {
  const double theta = opt_.initial_theta > 0 ? opt_.initial_theta
                                              : 1e-3 * pde_.geometry().gravity * pde_.model().sigma;
  return opt_.start == HydroRunOptions::Start::Spread ? spreadLayer(pde_, theta)
                                                      : settledLayer(pde_, theta);
}

HydroPhase HydroSimulation::snapshot(double t, const std::vector<double>& U) const {
  const int N = pde_.cells();
  const ConstitutiveModel& m = pde_.model();
  const double m_c = pde_.cellMass();
  HydroPhase p;
  p.time = t;
  p.plate_height = pde_.geometry().plateHeight(t);
  p.plate_velocity = pde_.geometry().plateVelocity(t);
  double mz = 0;
  for (int i = 0; i < N; ++i) {
    const double z0 = U[pde_.heightIndex(i)], z1 = U[pde_.heightIndex(i + 1)];
    const double rho = m_c / (z1 - z0);
    const double theta = pde_.temperature(U.data(), i);
    p.z.push_back(0.5 * (z0 + z1));
    p.n.push_back(rho / m.mass);
    p.u.push_back(0.5 * (U[pde_.velocityIndex(i)] + U[pde_.velocityIndex(i + 1)]));
    p.theta.push_back(theta);
    if (pde_.rough()) p.rotation.push_back(pde_.rotationalTemperature(U.data(), i));
    p.area_fraction.push_back(m.areaFraction(rho));
    p.pressure.push_back(
        m.pressure(std::min(rho, 0.999999 * m.packingLimit() * m.mass / m.diskArea()), theta));
    mz += p.z.back();
  }
  p.center_of_mass_height = mz / N;  // cells of equal mass
  p.layer_bottom = U[pde_.heightIndex(0)];
  p.layer_top = U[pde_.heightIndex(N)];
  return p;
}

CvodeOptions HydroSimulation::solverOptions() {
  const HydroGeometry& g = pde_.geometry();
  const double sigma = pde_.model().sigma;
  const int N = pde_.cells();
  CvodeOptions co = opt_.cvode;
  if (co.atol.empty()) {
    const double a = opt_.atol_scale;
    co.atol.assign(pde_.size(), 0.0);
    for (int j = 0; j <= N; ++j) {
      co.atol[pde_.heightIndex(j)] = 100 * a * sigma;
      co.atol[pde_.velocityIndex(j)] = 100 * a * std::sqrt(g.gravity * sigma);
      // ln theta: an absolute error in it is a relative error of the temperature.
      if (j < N) co.atol[pde_.temperatureIndex(j)] = 1e4 * a;
      if (j < N && pde_.rough()) co.atol[pde_.rotationIndex(j)] = 1e4 * a;
    }
    // The budget's quadratures take no part in the error test (their weight is nil).
    for (int k = pde_.layerSize(); k < pde_.size(); ++k) co.atol[k] = 1e30;
  }
  if (co.band_upper == 0) co.band_upper = co.band_lower = pde_.halfBand();
  const double T = 2 * std::numbers::pi / g.omega;
  if (co.max_step == 0) co.max_step = T / (2 * opt_.samples_per_cycle);
  co.max_steps = stepBudget();  // per output interval: at most a cycle's budget
  if (opt_.exact_jacobian && co.method == CvodeMethod::BdfBanded && !co.jacobian)
    co.jacobian = [this](double t, const double* y, const BandMatrixWriter& w) {
      return pde_.jacobian(t, y, w, hold_);
    };
  if (pde_.hardWalls()) {
    co.events = 2;
    co.event_functions = [this](double t, const double* y, double* g) {
      pde_.wallEvents(t, y, hold_, g);
    };
    co.on_event = [this](double t, std::vector<double>& y, const std::vector<int>& found) {
      hold_ = pde_.wallEvent(t, y, hold_, found);
    };
  }
  return co;
}

// max_step = T / (2 M) forces 2 M steps a cycle whatever the layer does: those are no sign
// of a stalled solver, so the budget is on top of them.
long HydroSimulation::stepBudget() const {
  return opt_.max_steps_per_cycle + 2L * opt_.samples_per_cycle;
}

int HydroSimulation::detectPeriod(const std::vector<double>& h) const {
  const std::size_t M = static_cast<std::size_t>(opt_.samples_per_cycle);
  for (int P = 1; P <= opt_.max_period; ++P) {
    const std::size_t span = static_cast<std::size_t>(P) * M;
    if (h.size() < 2 * span) return 0;
    const auto [lo, hi] = std::minmax_element(h.end() - static_cast<long>(span), h.end());
    const double amp = std::max(*hi - *lo, 1e-12);
    double worst = 0;
    for (std::size_t k = 1; k <= span; ++k)
      worst = std::max(worst, std::abs(h[h.size() - k] - h[h.size() - k - span]));
    if (worst <= opt_.periodic_tolerance * amp) return P;
  }
  return 0;
}

HydroRegime HydroSimulation::classify(const std::vector<HydroPhase>& window) const {
  const ConstitutiveModel& m = pde_.model();
  double lo = 1e300, hi = -1e300, dilated = 0;
  for (const HydroPhase& ph : window) {
    lo = std::min(lo, ph.center_of_mass_height);
    hi = std::max(hi, ph.center_of_mass_height);
    const auto loose = std::count_if(ph.area_fraction.begin(), ph.area_fraction.end(),
                                     [&](double nu) { return nu < m.contact.onset; });
    dilated = std::max(dilated, static_cast<double>(loose) / ph.area_fraction.size());
  }
  // Leaving the plate by less than 1 % of a diameter is resting on it; a layer of which never
  // more than 10 % of the mass dilates below the contact onset moves as one block.
  if (hi - lo < 0.01 * m.sigma) return HydroRegime::AtRest;
  return dilated < 0.1 ? HydroRegime::Solid : HydroRegime::Fluidised;
}

HydroResult HydroSimulation::run() {
  const double cpu0 = threadCpuSeconds();
  const HydroGeometry& g = pde_.geometry();
  const int M = opt_.samples_per_cycle;
  const double T = 2 * std::numbers::pi / g.omega;
  const int ramp = static_cast<int>(std::ceil(g.ramp_time / T - 1e-9));

  HydroResult r;
  const std::vector<double> start = initialState();
  hold_ = pde_.startingHold(0.0, start.data());
  CvodeIntegrator cv(
      [this](double t, const double* y, double* yd) { return pde_.rightHandSide(t, y, yd, hold_); },
      0.0, start, solverOptions(), [this](int k) { return pde_.componentName(k); });

  std::vector<HydroPhase> recent;  // the last max_period cycles of phases
  const std::size_t keep = static_cast<std::size_t>(opt_.max_period) * M;
  long steps_before = 0;
  for (int cycle = 0; cycle < opt_.max_cycles; ++cycle) {
    for (int k = 1; k <= M; ++k) {
      const double t = (cycle + static_cast<double>(k) / M) * T;
      PhaseBudget budget;
      try {
        budget = advanceWithBudget(pde_, cv, t);
      } catch (const CvodeError& e) {
        throw HydroFailure(std::string(e.what()) + " (cycle " + std::to_string(cycle + 1) + ")",
                           e.time(), cycle + 1);
      }
      if (!pde_.withinWalls(cv.state().data()))
        throw HydroFailure("a boundary node passed through its wall at t = " + std::to_string(t) +
                               " s (cycle " + std::to_string(cycle + 1) +
                               "): a landing the hard wall's event detection missed",
                           t, cycle + 1);
      if (opt_.interrupt && opt_.interrupt->load())
        throw HydroInterrupted("interrupted at t = " + std::to_string(t) + " s");
      HydroPhase ph = snapshot(t, cv.state());
      ph.budget = budget;
      r.com_per_phase.push_back(ph.center_of_mass_height);
      recent.push_back(std::move(ph));
      if (recent.size() > keep) recent.erase(recent.begin());
    }
    const long steps = cv.stats().steps;
    r.steps_per_cycle.push_back(steps - steps_before);
    steps_before = steps;
    r.cycles = cycle + 1;
    if (r.steps_per_cycle.back() > stepBudget())
      throw HydroFailure("no progress: cycle " + std::to_string(r.cycles) + " needed " +
                             std::to_string(r.steps_per_cycle.back()) + " steps (budget " +
                             std::to_string(stepBudget()) + "), last step " +
                             std::to_string(cv.stats().last_step) + " s",
                         cv.time(), r.cycles);
    if (r.cycles < ramp + opt_.min_cycles) continue;
    // Only cycles after the ramp count as the periodic state.
    const std::vector<double> settled(r.com_per_phase.begin() + static_cast<long>(ramp) * M,
                                      r.com_per_phase.end());
    r.period = detectPeriod(settled);
    if (r.period > 0) break;
  }
  r.periodic = r.period > 0;
  const int P = r.periodic ? r.period : std::min(opt_.max_period, 2);
  r.window.assign(recent.end() - static_cast<long>(P) * M, recent.end());
  r.regime = classify(r.window);
  r.stats = cv.stats();
  r.cpu_seconds = threadCpuSeconds() - cpu0;
  return r;
}

}  // namespace granwave::hydro
