// Validation: equation of state of elastic hard disks (e = 1) in a fully periodic box,
// measured with the engine's 2D virial pressure, P A = E_kin + (1 / 2t) sum_coll r_ij . dp_i.
//
// Compressibility factor Z = P A / (N T), T = E_kin / N (kinetic energy per particle; in 2D
// E_kin = N T). References:
//   Henderson (1975), Mol. Phys. 30, 971:
//       Z_H = 1 + 2 phi g2,  g2 = (1 - 7 phi / 16) / (1 - phi)^2,
//       equivalently Z_H = (1 + phi^2 / 8) / (1 - phi)^2;
//   Luding (2001), Phys. Rev. E 63, 042201, corrected fluid branch:
//       Z_L = 1 + 2 phi g4,  g4 = g2 - phi^3 / (128 (1 - phi)^4).
//   Z_L agrees with the hard-disk virial series (Clisby & McCoy 2006, B2..B10) and with Liu's
//   fluid EOS (arXiv:2010.10624, 2020) to ~0.1 % for phi <= 0.6; Henderson is high by 0.03 %
//   (phi 0.3), 0.4 % (0.5) and 1.2 % (0.6).
//
// Statistics (the same for all tests below). Each block is one record interval of 10 Enskog
// collision times per particle (the engine resets its virial accumulator at each record);
// Z is the mean of the block values and sigma its standard error. The blocks are checked to be
// independent: the standard error from blocks of 2 and 4 record intervals must agree with the
// one from single intervals (a correlated series would make it grow), and sigma is the largest
// of the three. Tolerances are 4 sigma and nothing else.
//
// Measured once with long runs of this engine (scratch study, 2e7 collisions each, N = 500,
// 1024, 2000, 4096), used only to choose N and the run length and to state what to expect:
//   * sigma / Z = 0.019 % x sqrt(2e7 / collisions) at phi 0.5 (0.013 % at 0.3, 0.021 % at 0.6),
//     independent of N; the 2.5e6 collisions here give 0.036 %, 0.053 %, 0.060 %.
//   * Finite-N shift Z(N) - Z(inf) ~ c / N with c ~ 0.3 (phi 0.3), 4.6 (0.5), 4-7 (0.6): at
//     N = 2000 this is 0.01-0.06 %, at most one sigma of these runs. (Part of it is kinematic:
//     with zero total momentum the temperature is E_kin / (N - 1), not E_kin / N.)
//   * Long-run values at N = 2000: Z(0.3) = 2.0633(3), Z(0.5) = 4.1069(8), Z(0.6) = 6.4582(14)
//     (6.4547(14) at N = 4096, 6.4616(14) at N = 500).
// Runtime: about 3 s per test in a Release build (2.5e6 collisions).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <vector>

#include "particles/EdSimulation.hpp"
#include "particles/InitialState.hpp"
#include "scene/Scene.hpp"

namespace granwave {
namespace {

constexpr double kDiameter = 0.002;                 // m
constexpr double kMass = 1.08e-5;                   // kg, 2 mm glass bead
constexpr double kTemperature = kMass * 0.1 * 0.1;  // J, thermal speed sqrt(T/m) = 0.1 m/s
constexpr int kParticles = 2000;
constexpr int kEquilibrationBlocks = 5;       // 50 collisions per particle
constexpr int kBlocks = 250;                  // 2500 collisions per particle
constexpr double kCollisionsPerBlock = 10.0;  // per particle

double hendersonG2(double phi) { return (1.0 - 7.0 * phi / 16.0) / ((1.0 - phi) * (1.0 - phi)); }
double hendersonZ(double phi) { return 1.0 + 2.0 * phi * hendersonG2(phi); }
double ludingZ(double phi) {
  const double g4 = hendersonG2(phi) - phi * phi * phi / (128.0 * std::pow(1.0 - phi, 4));
  return 1.0 + 2.0 * phi * g4;
}
// Enskog collision frequency per particle in 2D, omega_E = 2 n d g2 sqrt(pi T / m).
double enskogFrequency(double phi) {
  const double n = 4.0 * phi / (std::numbers::pi * kDiameter * kDiameter);
  return 2.0 * n * kDiameter * hendersonG2(phi) *
         std::sqrt(std::numbers::pi * kTemperature / kMass);
}

class CompressibilityRecorder : public SnapshotObserver {
 public:
  explicit CompressibilityRecorder(double area) : area_(area) {}
  void observe(const Snapshot& s) override {
    time.push_back(s.time);
    z.push_back(s.obs.pressure * area_ / s.obs.kinetic_energy);  // P A / (N T), N T = E_kin
  }
  std::vector<double> time, z;

 private:
  double area_;
};

struct MeanAndError {
  double mean = 0, error = 0;
};

MeanAndError meanAndStandardError(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  const double mean = sum / v.size();
  double sq = 0;
  for (double x : v) sq += (x - mean) * (x - mean);
  return {mean, std::sqrt(sq / (v.size() - 1) / v.size())};
}

std::vector<double> mergePairs(const std::vector<double>& v) {
  std::vector<double> out;
  for (std::size_t k = 0; k + 1 < v.size(); k += 2) out.push_back(0.5 * (v[k] + v[k + 1]));
  return out;
}

struct EosMeasurement {
  double z = 0, sigma = 0;
  double error1 = 0, error2 = 0, error4 = 0;  // standard errors from blocks of 1, 2, 4 records
  int blocks = 0;
};

EosMeasurement measureCompressibility(double phi, std::uint64_t seed) {
  EngineConfig c;
  c.diameter = kDiameter;
  c.mass = kMass;
  c.gravity = 0;
  c.width = c.height =
      std::sqrt(kParticles * std::numbers::pi * kDiameter * kDiameter / (4.0 * phi));
  c.periodic_x = c.periodic_z = true;
  c.plate = {};  // no drive
  c.restitution = Restitution::constant(1.0);
  c.tc = 0;
  c.record_interval = kCollisionsPerBlock / enskogFrequency(phi);
  c.duration = (kEquilibrationBlocks + kBlocks) * c.record_interval;

  Scene scene;
  scene.particles.count = kParticles;
  scene.initial.temperature = kTemperature;
  scene.initial.placement = phi >= 0.5 ? InitialPlacement::Lattice : InitialPlacement::Random;
  scene.run.seed = seed;

  EdSimulation sim(c, initialCondition(scene, c));
  CompressibilityRecorder rec(c.width * c.height);
  sim.addObserver(&rec);
  const RunStatus status = sim.run();
  EXPECT_TRUE(status.completed);

  // Record k (k >= 1) holds the virial of ((k-1) dt, k dt]; record 0 (t = 0) holds none.
  std::vector<double> blocks;
  for (std::size_t k = kEquilibrationBlocks + 1; k < rec.z.size(); ++k) blocks.push_back(rec.z[k]);
  EosMeasurement m;
  m.blocks = static_cast<int>(blocks.size());
  const MeanAndError b1 = meanAndStandardError(blocks);
  const std::vector<double> twice = mergePairs(blocks);
  const std::vector<double> four = mergePairs(twice);
  m.z = b1.mean;
  m.error1 = b1.error;
  m.error2 = meanAndStandardError(twice).error;
  m.error4 = meanAndStandardError(four).error;
  m.sigma = std::max({m.error1, m.error2, m.error4});
  std::printf(
      "phi = %.2f, N = %d, %d blocks: Z = %.5f +- %.5f (%.3f %%); standard error from "
      "blocks of 1/2/4 records %.5f/%.5f/%.5f\n"
      "  Henderson Z = %.5f: (Z - Z_H) / Z_H = %+.3f %% +- %.3f %% (%+.1f sigma)\n"
      "  Luding    Z = %.5f: (Z - Z_L) / Z_L = %+.3f %% +- %.3f %% (%+.1f sigma)\n",
      phi, kParticles, m.blocks, m.z, m.sigma, 100 * m.sigma / m.z, m.error1, m.error2, m.error4,
      hendersonZ(phi), 100 * (m.z / hendersonZ(phi) - 1), 100 * m.sigma / hendersonZ(phi),
      (m.z - hendersonZ(phi)) / m.sigma, ludingZ(phi), 100 * (m.z / ludingZ(phi) - 1),
      100 * m.sigma / ludingZ(phi), (m.z - ludingZ(phi)) / m.sigma);
  return m;
}

// The blocks are independent if merging them does not increase the standard error. With M
// blocks the estimated standard error itself scatters by ~1/sqrt(2 (M - 1)): 4.5 % for 250
// blocks, 9 % for the 62 blocks of four records. A ratio below 1.35 is within ~3.5 of those
// scatters of 1; correlated blocks (e.g. too short record intervals) exceed it.
void expectIndependentBlocks(const EosMeasurement& m) {
  EXPECT_LT(m.error2 / m.error1, 1.35) << "pressure blocks are correlated";
  EXPECT_LT(m.error4 / m.error1, 1.35) << "pressure blocks are correlated";
}

TEST(EquationOfState, ElasticDisksAtAreaFraction030FollowHenderson) {
  // Theory: at phi = 0.3 Henderson's Z_H = 2.06378 is accurate to 0.03 % (virial series through
  // B10: 2.06326; Luding's Z_L = 2.06325). Statistics: 250 independent blocks give sigma ~
  // 0.036 % of Z (0.0008); Henderson's own error and the finite-N shift (0.01 %) are well
  // inside one sigma. Assertion: |Z - Z_H| < 4 sigma. Measured (seed 3): see the printed line.
  const EosMeasurement m = measureCompressibility(0.3, 3);
  expectIndependentBlocks(m);
  EXPECT_NEAR(m.z, hendersonZ(0.3), 4 * m.sigma);
  EXPECT_NEAR(m.z, ludingZ(0.3), 4 * m.sigma);
}

TEST(EquationOfState, ElasticDisksAtAreaFraction050FollowLudingAndLieJustBelowHenderson) {
  // Theory: Henderson's Z_H = 4.12500 is 0.4 % high at phi = 0.5 (Luding's corrected fluid branch
  // Z_L = 4.10938; Liu 2020: 4.1052; our N -> infinity extrapolation 4.1047). Henderson's
  // "better than 0.5 %" is thus a model error of 0.4 %, eight times the statistical error of
  // this run (sigma ~ 0.053 %, 0.0022), so it is resolved, not hidden in the tolerance.
  // Assertions: |Z - Z_L| < 4 sigma (Z_L's own 0.1 % excess is partly cancelled by the +0.06 %
  // finite-N shift at N = 2000; the long-run N = 2000 value 4.1069(8) lies 1.1 sigma of this run
  // below Z_L), and Henderson lies above the measurement by more than 4 sigma.
  // Measured (seed 5): see the printed line.
  const EosMeasurement m = measureCompressibility(0.5, 5);
  expectIndependentBlocks(m);
  EXPECT_NEAR(m.z, ludingZ(0.5), 4 * m.sigma);
  EXPECT_GT(hendersonZ(0.5) - m.z, 4 * m.sigma) << "Henderson is known to be ~0.4 % high here";
}

TEST(EquationOfState, ElasticDisksAtAreaFraction060LieAboutOnePercentBelowHenderson) {
  // Theory: at phi = 0.6 Henderson's Z_H = 6.53125 is 1.2 % high; Luding's corrected fluid
  // branch Z_L = 6.45215 (Liu 2020: 6.4520) is not. Long runs of this engine give 6.4582(14)
  // for N = 2000 and 6.4547(14) for N = 4096, i.e. (Z_H - Z) / Z_H = 1.1-1.2 %. Statistics:
  // sigma ~ 0.06 % (0.004) here, so the ~1 % deviation is resolved by ~18 sigma.
  // Assertions: Henderson above the measurement by more than 4 sigma; the measurement
  // consistent with Z_L within 4 sigma (i.e. the deviation from Henderson equals Luding's
  // 1.2 % within 4 sigma; the long-run N = 2000 value lies +0.09 %, 1.6 sigma of this run,
  // above Z_L, mostly the finite-N shift).
  // Measured (seed 7): see the printed line.
  const EosMeasurement m = measureCompressibility(0.6, 7);
  expectIndependentBlocks(m);
  EXPECT_GT(hendersonZ(0.6) - m.z, 4 * m.sigma) << "Henderson is known to be ~1 % high here";
  EXPECT_NEAR(m.z, ludingZ(0.6), 4 * m.sigma);
  const double deviation = 1.0 - m.z / hendersonZ(0.6);
  const double deviation_error = m.sigma / hendersonZ(0.6);
  std::printf("  Henderson above the measurement by %.3f %% +- %.3f %% (Luding: %.3f %%)\n",
              100 * deviation, 100 * deviation_error, 100 * (1.0 - ludingZ(0.6) / hendersonZ(0.6)));
}

}  // namespace
}  // namespace granwave
