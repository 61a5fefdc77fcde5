// Phase-averaged fields on synthetic input with known answers: a Maxwellian gas of known
// temperature and drift placed in known cells.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "coarse_grain/PhaseAverager.hpp"
#include "coarse_grain/PhaseFields.hpp"

using namespace granwave;

namespace {
constexpr double kMass = 1e-5, kD = 0.002;

FieldGrid grid4x4() {
  FieldGrid g;
  g.nx = 4;
  g.nz = 4;
  g.wx = g.wz = kD;
  return g;
}
}  // namespace

TEST(PhaseFields, MaxwellianGasGivesItsTemperatureAndDriftInEachCell) {
  // n particles per cell with velocity components ~ N(u, T/m): the estimator
  // m sum (v - v~)^2 / (2 n) has mean T (n - 1)/n (the paper's definition subtracts the sample
  // mean) and relative standard deviation 1/sqrt(n - 1) (chi^2 with 2(n - 1) degrees of freedom).
  const double T = 3e-6, ux = 0.1, uz = -0.2;
  const int per_cell = 2000;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> vel(0.0, std::sqrt(T / kMass));
  std::uniform_real_distribution<double> in(0.1, 0.9);
  PhaseAveragerConfig c;
  c.grid = grid4x4();
  c.samples_per_cycle = 1;
  c.cycles_per_window = 1;
  c.blocks = 2;
  c.total_cycles = 2;
  c.fixed_discard = 0;
  PhaseAverager av(c);
  for (int cycle = 0; cycle < 2; ++cycle) {
    Snapshot s;
    s.step = cycle;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        for (int k = 0; k < per_cell / 2; ++k) {
          s.x.push_back((i + in(rng)) * kD);
          s.z.push_back((j + in(rng)) * kD);
          s.vx.push_back(ux + vel(rng));
          s.vz.push_back(uz + vel(rng));
          s.omega.push_back(0);
        }
    av.observe(s);
  }
  const PhaseFields f = computeFields(av.accumulator(), {kMass, 0, kD, 3});
  const double n = per_cell;
  const double sigma_T = T / std::sqrt(n - 1), sigma_u = std::sqrt(T / kMass / n);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const std::size_t k = f.cell(0, j, i);
      EXPECT_EQ(f.count[k], n);
      EXPECT_NEAR(f.temperature[k], T * (n - 1) / n, 4 * sigma_T);
      EXPECT_NEAR(f.velocity_x[k], ux, 4 * sigma_u);
      EXPECT_NEAR(f.velocity_z[k], uz, 4 * sigma_u);
      // per snapshot: 1000 disks of area pi d^2/4 in a d x d cell
      EXPECT_NEAR(f.area_fraction[k], 1000 * M_PI / 4, 1e-9);
    }
  // Profiles: the row mean of T over 4 cells; RMS of v_x across columns ~ sigma_u.
  EXPECT_NEAR(f.profile_temperature[f.row(0, 2)], T * (n - 1) / n, 4 * sigma_T / 2);
  EXPECT_LT(f.profile_rms_velocity_x[f.row(0, 2)], 4 * sigma_u);
}

TEST(PhaseFields, CellsWithFewerThanThreeParticlesAreNotValid) {
  PhaseAccumulator acc(grid4x4(), 1, 1);
  acc.countSnapshot(0, 0, 0.0, 2);
  acc.add(0, 0, 0.5 * kD, 0.5 * kD, 1.0, 0.0, 0.0);
  acc.add(0, 0, 0.5 * kD, 0.5 * kD, -1.0, 0.0, 0.0);
  const PhaseFields f = computeFields(acc, {kMass, 0, kD, 3});
  EXPECT_EQ(f.count[f.cell(0, 0, 0)], 2);
  EXPECT_TRUE(std::isnan(f.temperature[f.cell(0, 0, 0)]));
  EXPECT_TRUE(std::isnan(f.profile_temperature[f.row(0, 0)]));
}

TEST(PhaseFields, WindowOfTwoCyclesKeepsAlternateCyclesApart) {
  // A period-2 layer: particles in row 0 in even cycles, row 3 in odd ones.
  PhaseAveragerConfig c;
  c.grid = grid4x4();
  c.samples_per_cycle = 1;
  c.cycles_per_window = 2;
  c.blocks = 2;
  c.total_cycles = 8;
  c.fixed_discard = 0;
  PhaseAverager av(c);
  for (int cycle = 0; cycle < 8; ++cycle) {
    Snapshot s;
    s.step = cycle;
    s.x = {0.5 * kD};
    s.z = {(cycle % 2 == 0 ? 0.5 : 3.5) * kD};
    s.vx = {0};
    s.vz = {0};
    s.omega = {0};
    av.observe(s);
  }
  const PhaseFields f = computeFields(av.accumulator(), {kMass, 0, kD, 3});
  EXPECT_EQ(f.count[f.cell(0, 0, 0)], 4);
  EXPECT_EQ(f.count[f.cell(1, 3, 0)], 4);
  EXPECT_EQ(f.count[f.cell(0, 3, 0)], 0);
  EXPECT_NEAR(f.center_of_mass_height[1], 3.5 * kD, 1e-15);
}

namespace {

// Records of one particle at rest, with cumulative energies that grow by known amounts per
// phase: the walls' work by (phase + 1) mJ, the pair loss by 2 mJ, the wall loss by 0.5 mJ.
std::vector<Snapshot> budgetRun(int records, int per_cycle) {
  std::vector<Snapshot> run;
  double work = 0, pair = 0, wall = 0;
  for (int k = 0; k < records; ++k) {
    work += 1e-3 * (k % per_cycle + 1);
    pair += 2e-3;
    wall += 0.5e-3;
    Snapshot s;
    s.step = static_cast<std::uint64_t>(k);
    s.x = {0.5 * kD};
    s.z = {0.5 * kD};
    s.vx = s.vz = s.omega = {0};
    s.obs.wall_work = work;
    s.obs.dissipated_energy = pair + wall;
    s.obs.wall_dissipated_energy = wall;
    run.push_back(s);
  }
  return run;
}

PhaseAveragerConfig budgetConfig(int per_cycle) {
  PhaseAveragerConfig c;
  c.grid = grid4x4();
  c.samples_per_cycle = per_cycle;
  c.cycles_per_window = 1;
  c.blocks = 2;
  c.total_cycles = 6;
  c.fixed_discard = 2;
  return c;
}

}  // namespace

TEST(PhaseFields, EnergyBudgetPerPhaseIsTheIncrementSinceTheRecordBefore) {
  const int M = 4;
  PhaseAverager av(budgetConfig(M));
  for (const Snapshot& s : budgetRun(6 * M, M)) av.observe(s);
  const PhaseFields f = computeFields(av.accumulator(), {kMass, 0, kD, 3});
  ASSERT_EQ(f.plate_work.size(), static_cast<std::size_t>(M));
  for (int ph = 0; ph < M; ++ph) {
    EXPECT_NEAR(f.plate_work[ph], 1e-3 * (ph + 1), 1e-15) << ph;
    EXPECT_NEAR(f.pair_loss[ph], 2e-3, 1e-15) << ph;
    EXPECT_NEAR(f.wall_loss[ph], 0.5e-3, 1e-15) << ph;
  }
}

TEST(PhaseFields, AccumulatorWithoutABudgetGivesNone) {
  PhaseAccumulator acc(grid4x4(), 2, 1);
  acc.countSnapshot(0, 0, 0.0, 1);
  acc.add(0, 0, 0.5 * kD, 0.5 * kD, 0, 0, 0);
  const PhaseFields f = computeFields(acc, {kMass, 0, kD, 3});
  EXPECT_TRUE(f.plate_work.empty());
  EXPECT_TRUE(f.wall_loss.empty());
}

TEST(PhaseFields, FirstRecordOfARunCarriesNoBudgetAndDoesNotLowerItsPhasesMean) {
  const int M = 4;
  PhaseAveragerConfig c = budgetConfig(M);
  c.fixed_discard = 0;  // the very first record is pooled: nothing came before it
  PhaseAverager av(c);
  for (const Snapshot& s : budgetRun(6 * M, M)) av.observe(s);
  const PhaseFields f = computeFields(av.accumulator(), {kMass, 0, kD, 3});
  ASSERT_EQ(f.plate_work.size(), static_cast<std::size_t>(M));
  EXPECT_NEAR(f.plate_work[0], 1e-3, 1e-15);
  EXPECT_NEAR(f.pair_loss[0], 2e-3, 1e-15);
}

TEST(PhaseFields, ANonFiniteEnergyLeavesNoBudgetRatherThanNaNsAsData) {
  const int M = 4;
  PhaseAverager av(budgetConfig(M));
  std::vector<Snapshot> run = budgetRun(6 * M, M);
  for (Snapshot& s : run) s.obs.wall_dissipated_energy = NAN;  // a file without it
  for (const Snapshot& s : run) av.observe(s);
  EXPECT_FALSE(av.accumulator().hasBudget());
  EXPECT_TRUE(computeFields(av.accumulator(), {kMass, 0, kD, 3}).plate_work.empty());
}
