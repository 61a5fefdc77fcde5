// Wave-front tracking on a prescribed moving temperature peak: particles in a column of rows
// whose velocity spread is large only at the row of the front, which moves up at a known
// speed; the gas ahead drifts at a known velocity. The fit must recover both.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "coarse_grain/FieldsAnalysis.hpp"

using namespace granwave;

namespace {
constexpr double kMass = 1e-5, kD = 0.002, kT0 = 1e-6;

struct Synthetic {
  double speed;      // m/s, front speed
  double gas;        // m/s, drift of the gas above the front
  int phases = 100;  // M, one cycle per window
  double dt = 1e-3;  // s between phases
};

// The random draws of the synthetic gas, in one order for every snapshot.
struct Draws {
  std::mt19937_64 rng;
  std::normal_distribution<double> unit{0.0, 1.0};
  std::uniform_real_distribution<double> in{0.05, 0.95};
};

// Two particles per cell of an nx x nz grid at one phase of a cycle.
Snapshot phaseSnapshot(const Synthetic& sp, int nx, int nz, int cycle, int ph, Draws& r) {
  Snapshot s;
  s.step = static_cast<std::uint64_t>(cycle) * sp.phases + ph;
  // Front from z = 5 d at phase 10 rising at `speed` until phase 30; no front otherwise.
  const bool active = ph >= 10 && ph <= 30;
  const double zf = 5.5 * kD + sp.speed * (ph - 10) * sp.dt;
  for (int j = 0; j < nz; ++j) {
    const double zc = (j + 0.5) * kD;
    const double peak = active ? std::exp(-std::pow((zc - zf) / (1.5 * kD), 2)) : 0.0;
    const double T = kT0 * (0.1 + 1.5 * peak);  // background 0.1 T0, peak 1.6 T0
    const double drift = active && zc > zf + kD ? sp.gas : 0.0;
    for (int n = 0; n < 2 * nx; ++n) {
      const int i = n / 2;
      s.x.push_back((i + r.in(r.rng)) * kD);
      s.z.push_back(zc + (r.in(r.rng) - 0.5) * kD);
      s.vx.push_back(r.unit(r.rng) * std::sqrt(T / kMass));
      s.vz.push_back(drift + r.unit(r.rng) * std::sqrt(T / kMass));
      s.omega.push_back(0);
    }
  }
  return s;
}

FieldsAnalysis analyse(const Synthetic& sp, int cycles, std::uint64_t seed) {
  PhaseAveragerConfig c;
  c.grid.nx = 10;
  c.grid.nz = 40;
  c.grid.wx = c.grid.wz = kD;
  c.samples_per_cycle = sp.phases;
  c.cycles_per_window = 1;
  c.blocks = 4;
  c.total_cycles = cycles;
  c.fixed_discard = 0;
  PhaseAverager av(c);
  Draws draws{std::mt19937_64(seed)};
  for (int cycle = 0; cycle < cycles; ++cycle)
    for (int ph = 0; ph < sp.phases; ++ph)
      av.observe(phaseSnapshot(sp, c.grid.nx, c.grid.nz, cycle, ph, draws));
  FieldsContext ctx;
  ctx.diameter = kD;
  ctx.mass = kMass;
  ctx.T0 = kT0;
  ctx.frequency = 1.0 / (sp.phases * sp.dt);
  return analyseFields(av, ctx);
}
}  // namespace

TEST(WaveFront, RecoversPrescribedFrontSpeedWithinItsError) {
  const Synthetic sp{1.6, -0.3};
  const FieldsAnalysis a = analyse(sp, 40, 3);
  ASSERT_EQ(a.fronts.size(), 1u);
  const FrontEpisode& e = a.fronts[0];
  EXPECT_EQ(e.first_phase, 10);
  EXPECT_EQ(e.last_phase, 30);
  EXPECT_GT(e.blocks_used, 2);
  // Expected 1.6 m/s; the parabolic peak refinement is exact for a Gaussian peak up to the
  // sampling noise, which the stated error covers (3 sigma).
  EXPECT_NEAR(e.speed, 1.6, 3 * e.speed_error + 0.02) << "error " << e.speed_error;
  EXPECT_LT(e.speed_error, 0.2);
  // Gas above the front moves at -0.3 m/s: relative speed 1.9 m/s.
  EXPECT_NEAR(e.gas_velocity_ahead, -0.3, 0.05);
  EXPECT_NEAR(e.speed_relative, 1.9, 3 * e.speed_error + 0.05);
}

TEST(WaveFront, NoFrontWhenPeakStaysBelowHalfT0) {
  // Same synthetic gas but the threshold raised above the peak (1.6 T0): no episodes.
  PhaseFields f;
  f.phases = 1;
  f.nz = 3;
  f.nx = 1;
  f.profile_temperature = {0.2 * kT0, 0.4 * kT0, 0.3 * kT0};
  f.profile_area_fraction = {0.5, 0.5, 0.5};
  EXPECT_TRUE(std::isnan(frontHeights(f, 0.0, kD, kT0, {})[0]));
  f.profile_temperature[1] = 0.6 * kT0;
  EXPECT_NEAR(frontHeights(f, 0.0, kD, kT0, {})[0], 1.5 * kD, 0.5 * kD);
}

TEST(WaveFront, DiluteGasAboveTheLayerIsNotAFront) {
  PhaseFields f;
  f.phases = 1;
  f.nz = 3;
  f.nx = 1;
  f.profile_temperature = {0.2 * kT0, 0.6 * kT0, 4.0 * kT0};
  f.profile_area_fraction = {0.6, 0.5, 0.01};  // the hot top row is almost empty
  EXPECT_NEAR(frontHeights(f, 0.0, kD, kT0, {})[0], 1.5 * kD, 0.5 * kD);
}
