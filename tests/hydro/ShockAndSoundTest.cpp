// The PDE's waves against theory (physics-hydro.md 3.1, 3.2; tests 4 and 5 of section 7):
// a strong shock reflected from a wall into a uniform gas against the Rankine-Hugoniot
// speed and post-shock temperature, and a small pulse against the adiabatic sound speed.
// Elastic particles (e = 1) so that no cooling acts behind the waves; no gravity.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "HydroTestSupport.hpp"
#include "hydro/CvodeIntegrator.hpp"
#include "hydro/GranularHydro1D.hpp"
#include "hydro/ShockRelations.hpp"
#include "hydro/SoundSpeed.hpp"

using namespace granwave::hydro;

namespace {
using test::kDisk;
using test::kMass;

struct Setup {
  GranularHydro1D pde;
  std::vector<double> U;
};

GranularHydro1D elasticPde(int cells, double height) {
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::constant(1.0), RestitutionClosure::constant(1.0));
  HydroGeometry g;
  g.cells = cells;
  g.height = height;
  g.gravity = 0;
  return GranularHydro1D(g, m);
}

CvodeIntegrator integrate(const GranularHydro1D& pde, const std::vector<double>& U) {
  CvodeOptions o;
  o.rtol = 1e-6;
  o.atol.assign(U.size(), 1e-12);
  o.band_upper = o.band_lower = GranularHydro1D::kHalfBand;
  return CvodeIntegrator(
      [&pde](double t, const double* y, double* d) { return pde.rightHandSide(t, y, d); }, 0.0, U,
      o);
}
}  // namespace

TEST(HydroWaves, GasHittingAWallMakesTheRankineHugoniotShock) {
  // Uniform gas (nu1 = 0.3, theta1 = 1e-4 m^2/s^2, i.e. Mach ~ 20) moving at -U_p onto the
  // wall at z = 0: in the gas frame the wall is a piston moving at U_p, and the reflected
  // shock moves at s - U_p in the wall frame. Expected from the jump conditions (general
  // solver, finite upstream temperature). Tolerances: the front position is read where the
  // density crosses halfway between the states (shock width a few mean free paths, ~3 cells),
  // so the speed from two times is good to ~3 cells / distance travelled ~ 5 %; the plateau
  // temperature to 3 % (NS-order shocks have a temperature overshoot in the front, so the
  // plateau is sampled a quarter of the way from the wall to the front).
  const double nu1 = 0.3, theta1 = 1e-4, Up = 0.4;
  const GranularHydro1D pde = elasticPde(800, 0.06);
  const double rho1 = nu1 * kMass / kDisk;
  std::vector<double> U(pde.size());
  for (int i = 0; i < 800; ++i) {
    U[3 * i] = rho1;
    U[3 * i + 1] = -rho1 * Up;
    U[3 * i + 2] = rho1 * (0.5 * Up * Up + theta1);
  }
  const ShockSolution rh = rankineHugoniot({nu1, theta1}, Up, RestitutionClosure::constant(1.0));
  CvodeIntegrator cv = integrate(pde, U);
  auto front = [&]() {
    const auto& V = cv.state();
    const double half = 0.5 * (rh.nu + nu1) * kMass / kDisk;
    for (int i = 0; i + 1 < 800; ++i)
      if (V[3 * i] >= half && V[3 * (i + 1)] < half)
        return pde.cellCentre(i) + pde.dz() * (V[3 * i] - half) / (V[3 * i] - V[3 * (i + 1)]);
    return -1.0;
  };
  const double t1 = 0.010, t2 = 0.025;
  cv.advanceTo(t1);
  const double z1 = front();
  cv.advanceTo(t2);
  const double z2 = front();
  ASSERT_GT(z1, 0);
  ASSERT_GT(z2, z1);
  const double speed = (z2 - z1) / (t2 - t1);
  EXPECT_NEAR(speed, rh.speed - Up, 0.05 * (rh.speed - Up))
      << "shock speed in the wall frame; Rankine-Hugoniot s = " << rh.speed << " m/s";
  const auto& V = cv.state();
  const int plateau = static_cast<int>(0.75 * z2 / pde.dz());
  const double theta2 =
      V[3 * plateau + 2] / V[3 * plateau] - 0.5 * std::pow(V[3 * plateau + 1] / V[3 * plateau], 2);
  EXPECT_NEAR(theta2, rh.theta, 0.03 * rh.theta);
  EXPECT_NEAR(V[3 * plateau] / (kMass / kDisk), rh.nu, 0.03 * rh.nu);
}

TEST(HydroWaves, SmallPulseTravelsAtTheAdiabaticSoundSpeed) {
  // A right-running simple wave of relative amplitude 1e-3 in a uniform gas (nu = 0.4,
  // theta = 0.05 m^2/s^2): isentropic start, drho/rho = b(z), u = c_s b, and
  // d(theta) = (p / rho^2) d(rho) (d = 2, physics-hydro.md 3.1). Its peak must move at c_s
  // (Henderson's g2). At finite wavelength heat conduction makes sound partly isothermal
  // (omega D / c^2 ~ 0.1 for a 10 mm pulse), a Navier-Stokes dispersion that slows the peak:
  // measured -3.3 % for a 10 mm pulse and -1.35 % for 20 mm, converging to c_s as the
  // wavelength grows. Asserted: 20 mm pulse, 2 % (cell 0.5 mm, travel 120 mm).
  const double nu = 0.4, theta = 0.05;
  const int N = 1200;
  const GranularHydro1D pde = elasticPde(N, 0.6);
  const RestitutionClosure elastic = RestitutionClosure::constant(1.0);
  const double rho = nu * kMass / kDisk;
  const double c = adiabaticSoundSpeed(nu, theta, elastic);
  const double p0 = rho * theta * pressureFactor(nu, theta, elastic);
  std::vector<double> U(pde.size());
  const double z0 = 0.16, w = 0.02;
  for (int i = 0; i < N; ++i) {
    const double b = 1e-3 * std::exp(-std::pow((pde.cellCentre(i) - z0) / w, 2));
    const double r = rho * (1 + b), u = c * b, th = theta + p0 / (rho * rho) * rho * b;
    U[3 * i] = r;
    U[3 * i + 1] = r * u;
    U[3 * i + 2] = r * (th + 0.5 * u * u);
  }
  CvodeIntegrator cv = integrate(pde, U);
  const double t = 0.12 / c;
  cv.advanceTo(t);
  const auto& V = cv.state();
  int best = 0;
  for (int i = 1; i < N - 1; ++i)
    if (V[3 * i] > V[3 * best]) best = i;
  const double a = V[3 * (best - 1)], bb = V[3 * best], cc = V[3 * (best + 1)];
  const double peak = pde.cellCentre(best) + 0.5 * pde.dz() * (a - cc) / (a - 2 * bb + cc);
  EXPECT_NEAR((peak - z0) / t, c, 0.02 * c)
      << "c_s = " << c << " m/s; measured " << (peak - z0) / t;
}
