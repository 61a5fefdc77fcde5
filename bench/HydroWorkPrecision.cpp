// Work-precision data for the hydrodynamic solver (docs/performance.md), on the paper's dry
// scene (f = 10 Hz, Gamma = 4, dry law, Jenkins-Richman closures, Luding g2, contact
// pressure), each run from the settled layer to its periodic state; compared over the final
// window (the period), phase by phase:
//   temporal: 100 cells, rtol 1e-2 .. 1e-7 against rtol 1e-9 on the same grid
//   spatial:  rtol 1e-7, 25 .. 400 cells against 800 cells (the fine cells of equal mass
//             averaged onto the coarse ones: a Lagrangian grid compares in mass coordinates)
//   methods:  BDF + banded LU with the exact (automatically differentiated) Jacobian, with
//             CVODE's difference-quotient Jacobian, and BDF + GMRES with a band
//             preconditioner.
// Errors: relative L2 norm of the temperature over all compared phases and cells, and the
// largest centre-of-mass deviation over the window relative to its excursion.
// Cost: CPU seconds per drive cycle (this thread).
// Prints CSV: kind,method,cells,rtol,error_T,error_com,cpu_per_cycle,steps_per_cycle,status
//   granwave_hydro_wpd [--quick]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>

#include "hydro/HydroSimulation.hpp"

using namespace granwave::hydro;

namespace {
constexpr double kD = 0.002;
const double kMass = 2580 * std::numbers::pi * kD * kD * kD / 6;

enum class Method { ExactJacobian, DifferenceQuotients, Krylov };

struct Run {
  HydroResult result;
  std::string status = "ok";
};

Run simulate(int cells, double rtol, Method method) {
  ConstitutiveModel m;
  m.mass = kMass;
  m.sigma = kD;
  m.restitution = RestitutionClosure::dry(0.1);
  m.wall_restitution = m.restitution;
  m.knudsen_length = kD;
  m.contact.scale = kHexagonalClosePacking * kMass / m.diskArea() * 9.81 * kD;
  HydroGeometry g;
  g.cells = cells;
  g.height = 30 * kD;
  g.omega = 2 * std::numbers::pi * 10;
  g.amplitude = 4 * 9.81 / (g.omega * g.omega);
  g.ramp_time = 0.2;
  const GranularHydro1D pde(g, m, 300 * kMass / (30 * kD));
  HydroRunOptions o;
  o.samples_per_cycle = 50;
  o.cvode.rtol = rtol;
  o.cvode.method = method == Method::Krylov ? CvodeMethod::BdfKrylov : CvodeMethod::BdfBanded;
  o.exact_jacobian = method == Method::ExactJacobian;
  o.max_steps_per_cycle = 200000;
  HydroSimulation sim(pde, o);
  Run r;
  try {
    r.result = sim.run();
    if (!r.result.periodic) r.status = "not periodic";
  } catch (const std::exception& e) {
    r.status = std::string("error: ") + e.what();
  }
  return r;
}

// Temperature over the window, averaged onto `cells` cells of equal mass.
std::vector<double> temperature(const HydroResult& r, int cells) {
  std::vector<double> out;
  for (const HydroPhase& ph : r.window) {
    const int fine = static_cast<int>(ph.theta.size()), k = fine / cells;
    for (int c = 0; c < cells; ++c) {
      double s = 0;
      for (int j = 0; j < k; ++j) s += ph.theta[c * k + j] / k;
      out.push_back(s);
    }
  }
  return out;
}

double relL2(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.empty()) return NAN;
  double num = 0, den = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    num += (a[i] - b[i]) * (a[i] - b[i]);
    den += b[i] * b[i];
  }
  return std::sqrt(num / den);
}

double comError(const HydroResult& r, const HydroResult& ref) {
  if (r.window.size() != ref.window.size()) return NAN;
  double lo = 1e300, hi = -1e300, worst = 0;
  for (std::size_t k = 0; k < ref.window.size(); ++k) {
    const double c = ref.window[k].center_of_mass_height;
    lo = std::min(lo, c);
    hi = std::max(hi, c);
    worst = std::max(worst, std::abs(r.window[k].center_of_mass_height - c));
  }
  return worst / (hi - lo);
}

const char* name(Method m) {
  return m == Method::ExactJacobian         ? "bdf-band-exact"
         : m == Method::DifferenceQuotients ? "bdf-band-dq"
                                            : "bdf-gmres";
}

void row(const char* kind, Method m, int cells, double rtol, const Run& r, const Run& ref) {
  const bool ok = r.status == "ok" && ref.status == "ok";
  const double eT = ok ? relL2(temperature(r.result, cells), temperature(ref.result, cells)) : NAN;
  const double eC = ok ? comError(r.result, ref.result) : NAN;
  const double cycles = std::max(r.result.cycles, 1);
  double steps = 0;
  for (long s : r.result.steps_per_cycle) steps += static_cast<double>(s);
  std::printf("%s,%s,%d,%.0e,%.3e,%.3e,%.4f,%.0f,%s\n", kind, name(m), cells, rtol, eT, eC,
              r.result.cpu_seconds / cycles, steps / cycles, r.status.c_str());
  std::fflush(stdout);
}
}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  std::printf("kind,method,cells,rtol,error_T,error_com,cpu_per_cycle,steps_per_cycle,status\n");
  const Run ref_t = simulate(100, 1e-9, Method::ExactJacobian);
  row("reference", Method::ExactJacobian, 100, 1e-9, ref_t, ref_t);
  for (Method m : {Method::ExactJacobian, Method::DifferenceQuotients, Method::Krylov}) {
    for (double rtol : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
      if (quick && (rtol < 1e-5 || m != Method::ExactJacobian)) continue;
      row("temporal", m, 100, rtol, simulate(100, rtol, m), ref_t);
    }
  }
  const int fine = quick ? 400 : 800;
  const Run ref_s = simulate(fine, 1e-7, Method::ExactJacobian);
  row("reference", Method::ExactJacobian, fine, 1e-7, ref_s, ref_s);
  for (int cells : {25, 50, 100, 200, 400}) {
    if (cells >= fine) continue;
    row("spatial", Method::ExactJacobian, cells, 1e-7, simulate(cells, 1e-7, Method::ExactJacobian),
        ref_s);
  }
  return 0;
}
