// Validation of the solid / fluid classifier (coarse_grain/StateClassifier.hpp) on layers of
// known state: elastic hard disks in equilibrium in a fully periodic box.
//
// Known states: the hard-disk phase diagram of Bernard & Krauth, PRL 107, 155704 (2011)
// (event-chain Monte Carlo, N up to 1024^2): liquid below area fraction phi = 0.700,
// liquid-hexatic coexistence 0.700-0.716, hexatic 0.716-0.720, solid above about 0.720.
// The classifier's thresholds (bond_cutoff 1.2 d, broken_beyond 1.5 d, caged_fraction 0.5,
// crystal_threshold 0.7) were argued from geometry and never fitted to these states; this test
// asks whether they give the known answer well away from the transition.
//
// Set-up: N = 400 disks on a triangular lattice commensurate with the box (20 columns, 20 rows),
// Maxwellian velocities, e = 1, no gravity, no TC. After 200 collisions per particle
// (the liquid melts from the lattice within a few tens), 16 snapshots 20 collisions per
// particle apart (Enskog frequency with Henderson's g2; its 10-20 % error in dense states
// only changes the spacing). The window is 300 collisions per particle, about the collisions
// a particle of the paper's fluidized layer makes in 15 drive cycles (of order 10^2 - 10^3).
//
// Expected: phi = 0.60 and 0.65 liquid-like (a liquid relaxes its cages within tens of
// collisions: B << 0.5); phi = 0.74 and 0.76 crystal (no cage breaks; hexatic order of a hot
// triangular crystal, <|psi6|> > 0.7). Between them the answer depends on the window and the
// start: measured once over 0.60-0.76 (docs/classification.md), 0.68 is amorphous (B = 0.55:
// a dense liquid near freezing keeps half its cages for 300 collisions) and 0.70 a crystal
// (the lattice has not melted at the coexistence boundary); neither is asserted.
// The within-cycle criterion (coarse_grain/WithinCycleState.hpp) is validated on the same
// windows with the same expectations: its isostatic coordination 4 and psi6 threshold 0.7 were
// argued from rigidity counting and lattice noise, not fitted.
// Runtime: about 0.6 s in a Release build.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "coarse_grain/StateClassifier.hpp"
#include "coarse_grain/WithinCycleState.hpp"
#include "particles/EdSimulation.hpp"
#include "particles/InitialState.hpp"
#include "scene/Scene.hpp"

namespace granwave {
namespace {

constexpr double kDiameter = 0.002;                 // m
constexpr double kMass = 1.08e-5;                   // kg
constexpr double kTemperature = kMass * 0.1 * 0.1;  // J
constexpr int kColumns = 20, kRows = 20;            // rows even: periodic in z
constexpr int kSnapshots = 16;
constexpr double kEquilibrationCollisions = 200, kCollisionsPerSnapshot = 20;

class SnapshotKeeper : public SnapshotObserver {
 public:
  void observe(const Snapshot& s) override { snapshots.push_back(s); }
  std::vector<Snapshot> snapshots;
};

double hendersonG2(double phi) { return (1.0 - 7.0 * phi / 16.0) / ((1.0 - phi) * (1.0 - phi)); }

struct EquilibriumWindow {
  std::vector<Snapshot> snapshots;
  double width = 0, height = 0;
};

EquilibriumWindow equilibriumDisks(double phi) {
  const double d = kDiameter;
  // Triangular lattice of spacing a filling the box at area fraction phi:
  // phi = (pi d^2 / 4) / (a^2 sqrt(3) / 2).
  const double a = d * std::sqrt(std::numbers::pi / (2.0 * std::sqrt(3.0) * phi));
  EngineConfig c;
  c.diameter = d;
  c.mass = kMass;
  c.gravity = 0;
  c.width = kColumns * a;
  c.height = kRows * a * std::sqrt(3.0) / 2.0;
  c.periodic_x = c.periodic_z = true;
  c.plate = {};
  c.restitution = Restitution::constant(1.0);
  c.tc = 0;
  const int n = kColumns * kRows;
  const double n_density = n / (c.width * c.height);
  const double enskog =
      2.0 * n_density * d * hendersonG2(phi) * std::sqrt(std::numbers::pi * kTemperature / kMass);
  c.record_interval = kCollisionsPerSnapshot / enskog;
  const double equilibration = kEquilibrationCollisions / enskog;
  c.duration = equilibration + (kSnapshots - 1) * c.record_interval + 1e-9 * c.record_interval;

  // Maxwellian velocities at kTemperature with zero total momentum (the engine's own initial
  // state, drawn in a dilute box; the velocities do not depend on the box), then the lattice.
  Scene scene;
  scene.particles.count = n;
  scene.initial.temperature = kTemperature;
  scene.initial.placement = InitialPlacement::Random;
  scene.run.seed = 11;
  EngineConfig dilute = c;
  dilute.width = dilute.height = 40 * kColumns * d;
  InitialCondition ic = initialCondition(scene, dilute);
  ic.x.clear();
  ic.z.clear();
  for (int r = 0; r < kRows; ++r)
    for (int k = 0; k < kColumns; ++k) {
      ic.x.push_back((k + 0.5 * (r % 2) + 0.25) * a);
      ic.z.push_back((r + 0.5) * a * std::sqrt(3.0) / 2.0);
    }

  // Records fall at multiples of record_interval from t = 0; the last kSnapshots of them, all
  // after the equilibration, are the window.
  EdSimulation sim(c, ic);
  SnapshotKeeper keep;
  sim.addObserver(&keep);
  const RunStatus status = sim.run();
  EXPECT_TRUE(status.completed);
  std::vector<Snapshot> window;
  for (const Snapshot& s : keep.snapshots)
    if (s.time >= equilibration - 1e-12) window.push_back(s);
  while (static_cast<int>(window.size()) > kSnapshots) window.erase(window.begin());
  EXPECT_EQ(static_cast<int>(window.size()), kSnapshots);
  // The classifier is periodic in x only (a layer has a floor): unwrap z through the periodic
  // boundary (a particle moves far less than H / 2 in 20 collisions), so that crossing it is not
  // read as a broken bond. Bonds across the z boundary in the first snapshot are not counted.
  for (std::size_t k = 1; k < window.size(); ++k)
    for (std::size_t j = 0; j < window[k].z.size(); ++j) {
      const double dz = window[k].z[j] - window[k - 1].z[j];
      window[k].z[j] -= c.height * std::round(dz / c.height);
    }
  return {window, c.width, c.height};
}

StateResult classifyEquilibriumDisks(double phi) {
  const EquilibriumWindow w = equilibriumDisks(phi);
  const StateResult r = classifyState(w.snapshots, w.width, kDiameter, true);
  std::printf("phi = %.2f: %s, bonds kept %.3f (per snapshot pair %.3f), <|psi6|> %.3f\n", phi,
              std::string(toString(r.state)).c_str(), r.bonds_kept, r.bonds_kept_per_cycle,
              r.mean_abs_psi6);
  return r;
}

// The within-cycle criterion (coarse_grain/WithinCycleState.hpp) on the same windows, cut into
// 4 "cycles" of 4 snapshots (80 collisions per particle each). Its coordination is the mean
// number of neighbours within 1.2 d; the lid is far away (plate at 0, height 10^3 box heights).
WithinCycleResult classifyEquilibriumDisksWithinCycles(double phi) {
  const EquilibriumWindow w = equilibriumDisks(phi);
  std::vector<std::vector<Snapshot>> cycles(4);
  for (std::size_t k = 0; k < w.snapshots.size(); ++k) cycles[k / 4].push_back(w.snapshots[k]);
  const WithinCycleResult r =
      classifyWithinCycles(cycles, w.width, 1e3 * w.height, kDiameter, true);
  std::printf("phi = %.2f within cycles: %s, crystal share %.2f, coordination %.2f, psi6 %.3f\n",
              phi, std::string(toString(r.state)).c_str(), r.crystal_share, r.coordination, r.psi6);
  return r;
}

TEST(StateClassifierOnHardDisks, EquilibriumLiquidBelowFreezingIsLiquidLike) {
  for (double phi : {0.60, 0.65}) {
    const StateResult r = classifyEquilibriumDisks(phi);
    EXPECT_EQ(r.state, LayerState::liquid_like) << "phi = " << phi;
    EXPECT_LT(r.bonds_kept, 0.5) << "phi = " << phi;
  }
}

TEST(StateClassifierOnHardDisks, EquilibriumSolidAboveMeltingIsACrystal) {
  for (double phi : {0.74, 0.76}) {
    const StateResult r = classifyEquilibriumDisks(phi);
    EXPECT_EQ(r.state, LayerState::crystal) << "phi = " << phi;
    EXPECT_GT(r.bonds_kept, 0.9) << "phi = " << phi;
    EXPECT_GT(r.mean_abs_psi6, 0.7) << "phi = " << phi;
  }
}

// Within one "cycle" a snapshot cannot show cage breaking; the criterion's coordination does the
// work. Measured once (docs/classification.md): z = 2.9, 3.5, 3.9 at phi = 0.60, 0.65, 0.68 and
// 4.2, 4.5, 4.9, 5.2 at 0.70-0.76. A snapshot of 400 disks has a coordination noise of about
// sqrt(6 / 400) / 2 ~ 0.06, so the margins below (0.5 from the isostatic 4) are many sigma.
TEST(StateClassifierOnHardDisks, WithinCycleEquilibriumLiquidBelowFreezingIsLiquidLike) {
  for (double phi : {0.60, 0.65}) {
    const WithinCycleResult r = classifyEquilibriumDisksWithinCycles(phi);
    EXPECT_EQ(r.state, LayerState::liquid_like) << "phi = " << phi;
    EXPECT_EQ(r.liquid_share, 1.0) << "phi = " << phi;
    EXPECT_LT(r.coordination, 4.0) << "phi = " << phi;
  }
}

TEST(StateClassifierOnHardDisks, WithinCycleEquilibriumSolidAboveMeltingIsACrystal) {
  for (double phi : {0.74, 0.76}) {
    const WithinCycleResult r = classifyEquilibriumDisksWithinCycles(phi);
    EXPECT_EQ(r.state, LayerState::crystal) << "phi = " << phi;
    EXPECT_EQ(r.crystal_share, 1.0) << "phi = " << phi;
    EXPECT_GT(r.coordination, 4.0) << "phi = " << phi;
    EXPECT_GT(r.psi6, 0.7) << "phi = " << phi;
  }
}

}  // namespace
}  // namespace granwave
