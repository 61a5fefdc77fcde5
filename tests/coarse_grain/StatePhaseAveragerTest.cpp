// Phase averages conditioned on the layer's state (coarse_grain/StatePhaseAverager.hpp) on a
// synthetic layer whose episodes, and the parity of its period-2 episodes, are known by
// construction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "coarse_grain/PeriodDetector.hpp"
#include "coarse_grain/PeriodDoublingSeries.hpp"
#include "coarse_grain/StatePhaseAverager.hpp"

using namespace granwave;

namespace {
constexpr int kM = 20, kCycles = 120;
constexpr double kSub = 0.002;  // m, f/2 amplitude in the period-2 episodes

// Centre-of-mass height at record k: the drive's motion, plus in cycles [48, 72) an f/2
// subharmonic and in cycles [84, 108) the same subharmonic one cycle later (the other parity).
double height(int k) {
  const double t = static_cast<double>(k) / kM;  // in cycles
  double h = 0.02 + 0.005 * std::sin(2 * std::numbers::pi * t);
  if (t >= 48 && t < 72) h += kSub * std::sin(std::numbers::pi * t);
  if (t >= 84 && t < 108) h += kSub * std::sin(std::numbers::pi * (t + 1));
  return h;
}

// Three particles whose mean height is height(k).
Snapshot snapshot(int k) {
  Snapshot s;
  s.step = static_cast<std::uint64_t>(k);
  const double h = height(k);
  s.x = {0.01, 0.03, 0.05};
  s.z = {h - 0.004, h, h + 0.004};
  s.vx = {0, 0, 0};
  s.vz = {0, 0, 0};
  s.omega = {0, 0, 0};
  s.obs.center_of_mass_height = h;
  return s;
}

PhaseAveragerConfig config() {
  PhaseAveragerConfig c;
  c.grid = FieldGrid::forContainer(0.06, 0.06, 0.01, 0.002);
  c.samples_per_cycle = kM;
  c.blocks = 2;
  c.total_cycles = kCycles;
  return c;
}
}  // namespace

TEST(StatePhaseAverager, PoolsEachWindowWithItsStateAndAlignsThePeriodTwoParity) {
  StatePhaseAverager av(config());
  for (int k = 0; k < kCycles * kM; ++k) av.observe(snapshot(k));
  // Windows from cycle 24 (a fifth of the run): 8 windows of 12 cycles; period 2 in the
  // windows starting at 48, 60, 84 and 96; the last two have the other parity.
  EXPECT_EQ(av.firstWindowCycle(), 24);
  EXPECT_EQ(av.windows(1), 4);
  EXPECT_EQ(av.windows(2), 4);
  EXPECT_EQ(av.swappedWindows(), 2);
  EXPECT_EQ(av.pooledCycles(2), 48);
  // The period-2 average keeps the subharmonic whole (both episodes on the same cycle of the
  // window; without the swap they would cancel), the period-1 average holds none of it.
  for (int ph = 0; ph < 2 * kM; ++ph) {
    const double t = static_cast<double>(ph) / kM;
    const double drive = 0.02 + 0.005 * std::sin(2 * std::numbers::pi * t);
    EXPECT_NEAR(av.accumulator(2).centerOfMass(-1, ph),
                drive + kSub * std::sin(std::numbers::pi * t), 1e-12)
        << "phase " << ph;
    EXPECT_NEAR(av.accumulator(1).centerOfMass(-1, ph), drive, 1e-12) << "phase " << ph;
  }
}

TEST(StatePhaseAverager, UsesTheSameWindowsAndStatesAsThePeriodDoublingSeries) {
  std::vector<double> com;
  for (int k = 0; k < kCycles * kM; ++k) com.push_back(height(k));
  const RunPeriod rp = runPeriod(com, kM);
  const PeriodDoublingSeries s = periodDoublingSeries(com, kM, rp.discarded);
  StatePhaseAverager av(config());
  for (int k = 0; k < kCycles * kM; ++k) av.observe(snapshot(k));
  EXPECT_EQ(s.first_cycle, av.firstWindowCycle());
  int p2 = 0;
  for (int v : s.period2) p2 += v;
  EXPECT_EQ(p2, av.windows(2));
  EXPECT_EQ(static_cast<int>(s.period2.size()) - p2, av.windows(1));
}
