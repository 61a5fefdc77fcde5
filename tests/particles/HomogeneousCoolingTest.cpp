// Validation: free cooling of a dilute gas of inelastic hard disks (constant restitution e, no
// friction, TC model off) in a fully periodic box without gravity: the homogeneous cooling
// state (HCS) and Haff's law.
//
// Theory (2D, disks of diameter d and mass m, T = kinetic energy per particle = m <v_x^2>).
//   Enskog collision frequency per particle: omega_E(T) = 2 n d g2(phi) sqrt(pi T / m), with
//   g2 = (1 - 7 phi / 16) / (1 - phi)^2 (Henderson 1975). [Cross-section length 2d; mean
//   relative speed of two Maxwellians sqrt(pi T / m); g2 raises the contact density.]
//   Energy balance: a collision dissipates (1 - e^2) (m/4) g_n^2 (reduced mass m/2; g_n the
//   normal approach speed). Collisions weight g_n by |g_n|, so with g_n ~ N(0, 2T/m) the
//   collision average is <g_n^2> = <|g_n|^3> / <|g_n|> = 4 T / m: (1 - e^2) T per collision.
//   There are N omega_E / 2 collisions per unit time and E_kin = N T, so
//       dT/dt = -(1 - e^2) omega_E(T) T / 2,   with omega_E ~ sqrt(T):
//       T(t) = T0 / (1 + t / tau)^2,   1/tau = (1 - e^2) omega_E(T0) / (2 d_dim), d_dim = 2
//   (Haff 1983, J. Fluid Mech. 134, 401; Brilliantov & Poeschel, Kinetic Theory of Granular
//   Gases, 2004). The factor is 1/2 in dT/dt, and 1/(2 d_dim) = 1/4 in 1/tau, consistently.
//   Equivalently 1/sqrt(T) = (1 + t / tau) / sqrt(T0) is linear in t with slope 1/(tau sqrt(T0)).
//
// Known deviations of a real (molecular-dynamics) HCS from this Maxwellian, uncorrelated theory:
//   (a) Sonine correction (van Noije & Ernst 1998, Granular Matter 1, 57): the HCS velocity
//       distribution has a2 = 16 (1 - e)(1 - 2 e^2) / (9 + 24 d - (41 - 8 d) e + 30 (1 - e) e^2),
//       d = 2: a2 = -0.027 (e = 0.9), -0.019 (e = 0.95) [negative for e > 1/sqrt(2)], and the
//       cooling rate is multiplied by (1 + 3 a2 / 16): 0.5 % (0.35 %) SLOWER cooling. The
//       engine's HCS shows a2 = -0.026 and -0.018 (32-seed scratch study), as predicted. The
//       Haff curve below ("Haff-Sonine") includes this factor explicitly.
//   (b) Velocity correlations: inelastic collisions correlate the velocities of neighbours
//       (long-range vortex correlations, van Noije, Ernst, Brito & Orza, PRL 79, 411 (1997); the
//       MD cooling rate is "slightly but distinctively smaller" than the Enskog-Sonine one from
//       the very start of the HCS, Kawahara & Nakanishi, arXiv:cond-mat/0309130; Nakanishi,
//       Phys. Rev. E 67 (2003), arXiv:cond-mat/0208477). Kinetic energy stored in correlated flow
//       is not dissipated at collisions, so the cooling rate drops by a fraction kappa that grows
//       with density and inelasticity. This engine (scratch study, 32-68 seeds, N = 4000) gives
//       kappa = 1.8 % (e = 0.9, phi = 0.05), 0.7-1.0 % (e = 0.95, phi = 0.05), 0.7 % (e = 0.9,
//       phi = 0.02), i.e. kappa = (1.4-2.1) (1 - e^2) phi; at the same time the kinetic energy
//       of the coarse-grained velocity field exceeds equipartition by 1-2 % of E_kin, while an
//       elastic gas shows none. No closed formula for kappa is available, so the tests allow
//       kappa <= kappa_max = 2.5 (1 - e^2) phi, an allowance set from those measurements and
//       ONE-SIDED: only slower cooling than Haff-Sonine is excused; faster cooling must agree
//       within statistics.
//   (c) Clustering / shear instability: phi = 0.05 and t <= 3 tau (about 30 (e = 0.9) or 60
//       (e = 0.95) collisions per particle) keep the system far from visible clustering; its
//       slow onset is part of (b).
//
// Statistics. The initial kinetic energy is exactly N T0 (initialCondition rescales it), so T(t)
// fluctuates only through the dissipation. Model: collisions form a Poisson process of rate
// N omega_E / 2, each losing an exponentially distributed energy of mean (1 - e^2) T (the
// collision-weighted g_n^2 is exponential), so Var(dT) = omega_E (1 - e^2)^2 T^2 dt / N. For
// u = 1/sqrt(T) the drift is deterministic (du/dt = 1 / (tau sqrt(T0))) and the noise is a
// Brownian motion W with Var W(s) = (1 - e^2) (s + s^2/2) / (N T0), s = t / tau. Hence
//       sigma[T / T_Haff](s) = 2 sqrt((1 - e^2) (s + s^2/2) / N) / (1 + s)     per run
// (N = 4000, s = 3: 0.94 % for e = 0.9, 0.68 % for e = 0.95), and the standard error of a
// least-squares slope of u(t) follows from the covariance Cov(W(s), W(s')) = Var W(min(s, s')).
// The 32-seed study confirms the model: observed scatter 0.85-1.15 times the prediction. Each
// test averages R independent runs (fixed seeds), so sigma / sqrt(R); tolerance 4 sigma.
//
// The sizes (N = 4000, phi = 0.05: box side 250 d) and R are chosen for a few seconds per test
// in a Release build.
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

constexpr double kDiameter = 0.002;        // m
constexpr double kMass = 1.08e-5;          // kg, 2 mm glass bead
constexpr double kT0 = kMass * 0.1 * 0.1;  // J, thermal speed sqrt(T0/m) = 0.1 m/s
constexpr int kParticles = 4000;
constexpr double kAreaFraction = 0.05;
constexpr int kDimension = 2;

double hendersonG2(double phi) { return (1.0 - 7.0 * phi / 16.0) / ((1.0 - phi) * (1.0 - phi)); }
double numberDensity() { return 4.0 * kAreaFraction / (std::numbers::pi * kDiameter * kDiameter); }
double enskogFrequency(double temperature) {
  return 2.0 * numberDensity() * kDiameter * hendersonG2(kAreaFraction) *
         std::sqrt(std::numbers::pi * temperature / kMass);
}
double haffTime(double e) { return 2.0 * kDimension / ((1.0 - e * e) * enskogFrequency(kT0)); }
// First Sonine coefficient of the HCS (van Noije & Ernst 1998), d = 2.
double sonineA2(double e) {
  const double d = kDimension;
  return 16.0 * (1.0 - e) * (1.0 - 2.0 * e * e) /
         (9.0 + 24.0 * d - (41.0 - 8.0 * d) * e + 30.0 * (1.0 - e) * e * e);
}
double sonineRateFactor(double e) { return 1.0 + 3.0 * sonineA2(e) / 16.0; }
// Velocity-correlation allowance on the cooling rate (see the header): one-sided.
double kappaMax(double e) { return 2.5 * (1.0 - e * e) * kAreaFraction; }

// Haff's law with the cooling rate multiplied by `rate` (1 = Enskog, Maxwellian).
double haffTemperature(double t, double tau, double rate) {
  const double x = 1.0 + rate * t / tau;
  return kT0 / (x * x);
}

// Noise model (header): variance of W(s) = u(t) - u_Haff(t), u = 1/sqrt(T), per run.
double inverseRootTVariance(double s, double e) {
  return (1.0 - e * e) * (s + 0.5 * s * s) / (kParticles * kT0);
}
double relativeTemperatureSigma(double s, double e) {
  return 2.0 * std::sqrt(inverseRootTVariance(s, e) * kT0) / (1.0 + s);
}

class CoolingRecorder : public SnapshotObserver {
 public:
  void observe(const Snapshot& s) override {
    time.push_back(s.time);
    temperature.push_back(s.obs.kinetic_energy / s.size());  // 2D: E_kin = N T
    pairs.push_back(s.obs.collisions.pair);
  }
  std::vector<double> time, temperature;
  std::vector<std::uint64_t> pairs;
};

CoolingRecorder runFreeCooling(double e, std::uint64_t seed, double duration, int records) {
  EngineConfig c;
  c.diameter = kDiameter;
  c.mass = kMass;
  c.gravity = 0;
  c.width = c.height =
      std::sqrt(kParticles * std::numbers::pi * kDiameter * kDiameter / (4.0 * kAreaFraction));
  c.periodic_x = c.periodic_z = true;
  c.plate = {};  // no drive
  c.restitution = Restitution::constant(e);
  c.tc = 0;  // TC model off
  c.duration = duration;
  c.record_interval = duration / records;

  Scene scene;
  scene.particles.count = kParticles;
  scene.initial.temperature = kT0;
  scene.initial.placement = InitialPlacement::Random;
  scene.run.seed = seed;

  EdSimulation sim(c, initialCondition(scene, c));
  CoolingRecorder rec;
  sim.addObserver(&rec);
  const RunStatus status = sim.run();
  EXPECT_TRUE(status.completed);
  EXPECT_EQ(static_cast<int>(rec.time.size()), records + 1);
  return rec;
}

constexpr double kWindow = 3.0;  // fit window in units of tau: T drops to ~1/16 of T0
constexpr int kRecords = 30;     // every 0.1 tau
constexpr int kReplicas = 6;

std::vector<CoolingRecorder> runReplicas(double e) {
  std::vector<CoolingRecorder> runs;
  for (int r = 0; r < kReplicas; ++r)
    runs.push_back(runFreeCooling(e, 1000 + r, kWindow * haffTime(e), kRecords));
  return runs;
}

// Replica-averaged T / T_Haff-Sonine against the one-sided band
//   1 - 4 sigma  <=  T / T_HS  <=  ((1 + s) / (1 + (1 - kappa_max) s))^2 + 4 sigma.
void checkHaffLaw(double e) {
  const double tau = haffTime(e);
  const double rate = sonineRateFactor(e);
  const std::vector<CoolingRecorder> runs = runReplicas(e);
  std::printf("e = %.2f: tau = %.4g s, a2 = %.4f, Sonine rate factor %.5f, kappa_max = %.4f\n", e,
              tau, sonineA2(e), rate, kappaMax(e));
  for (int k = 1; k <= kRecords; ++k) {
    const double t = runs[0].time[k];
    const double s = t / tau;
    double ratio = 0, ratio_plain = 0;
    for (const CoolingRecorder& run : runs) {
      ratio += run.temperature[k] / haffTemperature(t, tau, rate) / kReplicas;
      ratio_plain += run.temperature[k] / haffTemperature(t, tau, 1.0) / kReplicas;
    }
    const double sigma = relativeTemperatureSigma(s, e) / std::sqrt(kReplicas);
    const double slow = std::pow((1.0 + s) / (1.0 + (1.0 - kappaMax(e)) * s), 2);
    if (k % 5 == 0)
      std::printf(
          "  t = %.1f tau: T/T0 = %.4f, T/T_Haff = %.4f, T/T_Haff-Sonine = %.4f +- %.4f "
          "(band [%.4f, %.4f])\n",
          s, ratio_plain * haffTemperature(t, tau, 1.0) / kT0, ratio_plain, ratio, sigma,
          1 - 4 * sigma, slow + 4 * sigma);
    EXPECT_GT(ratio, 1.0 - 4.0 * sigma) << "cools faster than Haff-Sonine at t = " << s << " tau";
    EXPECT_LT(ratio, slow + 4.0 * sigma) << "cools slower than Haff-Sonine by more than the "
                                         << "velocity-correlation allowance at t = " << s << " tau";
  }
}

// Least-squares slope of u = 1/sqrt(T) against t over [0, 3 tau], averaged over replicas,
// against 1/(tau_HS sqrt(T0)); its standard error from the Brownian noise model.
void checkInverseRootSlope(double e) {
  const double tau = haffTime(e);
  const double rate = sonineRateFactor(e);
  const std::vector<CoolingRecorder> runs = runReplicas(e);
  const std::vector<double>& t = runs[0].time;
  const int m = static_cast<int>(t.size());
  double tmean = 0;
  for (double x : t) tmean += x / m;
  double sxx = 0;
  for (double x : t) sxx += (x - tmean) * (x - tmean);
  std::vector<double> w(m);
  for (int k = 0; k < m; ++k) w[k] = (t[k] - tmean) / sxx;  // slope = sum_k w_k u_k
  double var_slope = 0;
  for (int j = 0; j < m; ++j)
    for (int k = 0; k < m; ++k)
      var_slope += w[j] * w[k] * inverseRootTVariance(std::min(t[j], t[k]) / tau, e);
  double slope = 0;
  for (const CoolingRecorder& run : runs) {
    double b = 0;
    for (int k = 0; k < m; ++k) b += w[k] / std::sqrt(run.temperature[k]);
    slope += b / kReplicas;
  }
  const double haff = 1.0 / (tau * std::sqrt(kT0));
  const double expected = rate * haff;
  const double sigma = std::sqrt(var_slope / kReplicas) / expected;
  const double ratio = slope / expected;
  std::printf(
      "e = %.2f: slope of 1/sqrt(T) / Haff = %.4f, / Haff-Sonine = %.4f +- %.4f "
      "(band [%.4f, %.4f]; kappa = %.4f)\n",
      e, slope / haff, ratio, sigma, 1 - kappaMax(e) - 4 * sigma, 1 + 4 * sigma, 1 - ratio);
  EXPECT_GT(ratio, 1.0 - kappaMax(e) - 4.0 * sigma);
  EXPECT_LT(ratio, 1.0 + 4.0 * sigma);
}

TEST(HomogeneousCooling, CollisionFrequencyAtTheStartMatchesEnskog) {
  // Theory: omega_E = 2 n d g2 sqrt(pi T / m) (header), exact for an equilibrium hard-disk gas
  // at low density up to ring corrections (an elastic gas at phi = 0.05 gives 1.0014(7) omega_E
  // in this engine). At the start of free cooling the velocities are Maxwellian and uncorrelated,
  // so omega_E(T(t)) must hold; we skip the first collision time, in which the random-sequential
  // -addition positions relax to the equilibrium contact density, and count pair collisions in
  // [1, 5] / omega_E(T0) (about 0.05-0.24 tau at e = 0.9, when a2 and the velocity correlations
  // change omega by < 0.3 %). Expected count: (N/2) integral omega_E(T(t)) dt with the measured
  // T(t) (trapezoid on sqrt(T), records every 0.5 / omega_E(T0); discretisation error < 0.01 %).
  // Statistics: the count is Poisson (128-seed study of this window: scatter 1.03 sqrt(count),
  // mean ratio 0.9994(11)); 16 runs give ~1.1e5 collisions, sigma = 1/sqrt(count) ~ 0.3 %;
  // tolerance 4 sigma.
  const double e = 0.9;
  const double omega0 = enskogFrequency(kT0);
  const int replicas = 16;
  double counted = 0, expected = 0;
  for (int r = 0; r < replicas; ++r) {
    const CoolingRecorder run = runFreeCooling(e, 2000 + r, 5.0 / omega0, 10);
    for (int k = 3; k <= 10; ++k) {  // records at 0.5 k / omega0
      counted += static_cast<double>(run.pairs[k] - run.pairs[k - 1]);
      const double mean_omega =
          0.5 * (enskogFrequency(run.temperature[k]) + enskogFrequency(run.temperature[k - 1]));
      expected += 0.5 * kParticles * mean_omega * (run.time[k] - run.time[k - 1]);
    }
  }
  const double ratio = counted / expected;
  const double sigma = std::sqrt(counted) / expected;
  std::printf("collisions counted %.0f, Enskog %.1f: ratio %.4f +- %.4f\n", counted, expected,
              ratio, sigma);
  EXPECT_NEAR(ratio, 1.0, 4.0 * sigma);
}

TEST(HomogeneousCooling, TemperatureFollowsHaffsLawWithSonineCorrectionAtE090) {
  // Theory: Haff's law T = T0 / (1 + t/tau)^2, 1/tau = (1 - e^2) omega_E(T0) / 4 (Haff 1983,
  // Enskog rate), cooling rate times the Sonine factor 1 + 3 a2 / 16 (van Noije & Ernst 1998),
  // one-sided allowance kappa_max for velocity correlations; derivations and the noise model
  // in the header. Checked at every record (0.1 tau) up to 3 tau. e = 0.9: tau = 21 / omega_E(T0);
  // t = 3 tau after ~29 collisions per particle. Sonine: T / T_Haff = 1.0076 at 3 tau.
  // Statistics: per run sigma[T/T_Haff] = 0.94 % at 3 tau (0.73 % at 0.5 tau); 6 runs: 0.38 %.
  // Velocity correlations (32-seed study): T / T_Haff-Sonine = 1.026 at 3 tau (kappa = 1.8 %),
  // inside the allowance ((1 + s) / (1 + (1 - kappa_max) s))^2 = 1.037 (kappa_max = 2.4 %).
  checkHaffLaw(0.9);
}

TEST(HomogeneousCooling, TemperatureFollowsHaffsLawWithSonineCorrectionAtE095) {
  // Theory and tolerance as for e = 0.9 (Haff 1983; van Noije & Ernst 1998; header).
  // e = 0.95: tau = 41 / omega_E(T0), ~57 collisions per particle to 3 tau. Sonine factor
  // 0.9965. Statistics: per run sigma = 0.68 % at 3 tau (32-seed scatter 0.78 %); 6 runs: 0.28 %.
  // Velocity correlations: T / T_Haff-Sonine = 1.010-1.018 at 3 tau (kappa = 0.7-1.0 %),
  // allowance kappa_max = 1.2 %: upper bound 1.030.
  checkHaffLaw(0.95);
}

TEST(HomogeneousCooling, InverseRootTemperatureGrowsLinearlyAtHaffsRateAtE090) {
  // Theory: in Haff's law (Haff 1983) 1/sqrt(T) = (1 + t/tau) / sqrt(T0) is linear in t with
  // slope 1 / (tau sqrt(T0)), times the Sonine factor 0.9950 (van Noije & Ernst 1998); the
  // velocity-correlation allowance kappa_max = 2.4 % lowers the band, one-sided (header).
  // Least-squares slope over 31 records in [0, 3 tau]; noise model standard error per run
  // 0.69 % (32-seed scatter: 0.69 %), 6 runs: 0.28 %. Seed studies: slope / Haff-Sonine =
  // 0.979-0.987 (kappa = 1.3-2.1 %): lower bound 0.965, at least 5 sigma below every seed set.
  checkInverseRootSlope(0.9);
}

TEST(HomogeneousCooling, InverseRootTemperatureGrowsLinearlyAtHaffsRateAtE095) {
  // Theory as for e = 0.9 (Haff 1983; van Noije & Ernst 1998): Sonine factor 0.9965; standard
  // error per run 0.49 % (32-seed scatter 0.51 %), 6 runs 0.20 %. Seed studies: slope /
  // Haff-Sonine = 0.987-0.993 (kappa = 0.7-1.3 %), allowance kappa_max = 1.2 % (one-sided):
  // lower bound 0.980, at least 3.8 sigma below every seed set tried.
  checkInverseRootSlope(0.95);
}

}  // namespace
}  // namespace granwave
