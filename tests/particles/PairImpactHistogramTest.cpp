// The pair-impact normal-speed histogram (particles/PairImpactHistogram.hpp) against the
// equilibrium distribution of an elastic hard-disk gas.
//
// Expected (2D, equal masses m, temperature T, molecular chaos at contact): the relative
// velocity g of two disks is Gaussian with variance 2T/m per component, so its component
// along a fixed line of centres, v_n, has density ~ exp(-m v_n^2 / (4T)). Pairs approach and
// collide at a rate proportional to v_n (the flux through the contact line; the contact value of
// the pair correlation does not depend on velocity in equilibrium), so the normal speeds of the
// impacts have the density
//     p(v_n) = (m / 2T) v_n exp(-m v_n^2 / (4T)),   v_n > 0,
// cumulative F(v) = 1 - exp(-m v^2 / (4T)), mean sqrt(pi T / m), variance (4 - pi) T / m
// (e.g. Chapman & Cowling, The Mathematical Theory of Non-uniform Gases, ch. 5, in 2D).
//
// Tolerances from the counts: the bin counts are compared by Pearson's chi^2 with k - 1 degrees
// of freedom, asserted below k - 1 + 5 sqrt(2 (k - 1)) (5 sigma of the chi^2 distribution); the
// mean by 5 standard errors sqrt(var / n).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "EngineTestSupport.hpp"
#include "h5/H5Error.hpp"
#include "particles/H5mdWriter.hpp"
#include "particles/PairImpactHistogram.hpp"
#include "tests/h5/ScratchDir.hpp"

using namespace granwave;

TEST(PairImpactHistogram, ElasticHardDiskGasHasTheCollisionWeightedMaxwellDistribution) {
  const Scene s = test::periodicGas(400, 0.3, 1.08e-5 * 0.01, 1.0);
  EdSimulation sim = test::makeSimulation(s);
  const double mass = sim.config().mass;
  sim.advanceTo(0.5);  // equilibrate: ~50 collisions per particle
  const Snapshot snap = sim.snapshot();
  double kinetic = 0;
  for (int i = 0; i < snap.size(); ++i)
    kinetic += 0.5 * mass * (snap.vx[i] * snap.vx[i] + snap.vz[i] * snap.vz[i]);
  const double T = kinetic / (snap.size() - 1);  // zero total momentum: N - 1 free particles
  PairImpactBins bins;
  bins.speed_max = 5 * std::sqrt(2 * T / mass);
  bins.speed_bins = 30;
  bins.start_time = 0.5;
  PairImpactHistogram h(bins);
  sim.setPairImpactObserver(&h);
  sim.advanceTo(3.0);
  const double n = static_cast<double>(h.total());
  ASSERT_GT(n, 5e4);
  auto F = [&](double v) { return 1 - std::exp(-mass * v * v / (4 * T)); };
  double chi2 = 0, mean = 0;
  for (int k = 0; k < bins.speed_bins; ++k) {
    const double lo = k * bins.speed_max / bins.speed_bins;
    const double hi = k + 1 == bins.speed_bins ? INFINITY : lo + bins.speed_max / bins.speed_bins;
    const double expected = n * (F(hi) - F(lo));
    const double observed = static_cast<double>(h.count(0, k));
    chi2 += (observed - expected) * (observed - expected) / expected;
  }
  const int dof = bins.speed_bins - 1;
  EXPECT_LT(chi2, dof + 5 * std::sqrt(2.0 * dof)) << "Pearson chi^2 over " << dof << " dof";
  mean = h.weightedMean([](double v) { return v; });
  const double expected_mean = std::sqrt(std::numbers::pi * T / mass);
  const double error = std::sqrt((4 - std::numbers::pi) * T / mass / n);
  // Bin centres shift the mean of a smooth density by O(width^2): (v_max/30)^2 p'/p ~ 1e-3 of
  // it, below the 5 sigma = 4e-3 relative allowed here.
  EXPECT_NEAR(mean, expected_mean, 5 * error + 1e-3 * expected_mean);
}

TEST(PairImpactHistogram, ImpactsAreBinnedByPhaseSpeedAndHeight) {
  PairImpactBins b;
  b.speed_max = 1.0;
  b.speed_bins = 10;
  b.period = 0.2;
  b.phase_bins = 4;
  b.start_time = 1.0;
  b.z_max = 0.05;
  PairImpactHistogram h(b);
  h.pairImpact({0.5, 0.35, 0.01, false});   // before start_time: not counted
  h.pairImpact({1.06, 0.35, 0.01, false});  // phase 0.3 of 0.2 s -> bin 1; speed bin 3
  h.pairImpact({1.19, 7.0, 0.01, true});    // phase 0.95 -> bin 3; overflow -> last bin
  h.pairImpact({1.06, 0.35, 0.06, false});  // above z_max: not counted
  EXPECT_EQ(h.total(), 2u);
  EXPECT_EQ(h.count(1, 3), 1u);
  EXPECT_EQ(h.count(3, 9), 1u);
  EXPECT_DOUBLE_EQ(h.weightedMean([](double v) { return v; }, {false, true, false, false}), 0.35);
  EXPECT_THROW(PairImpactHistogram(PairImpactBins{0.0}), std::invalid_argument);
}

namespace {

PairImpactBins phaseResolvedBins() {
  PairImpactBins b;
  b.speed_max = 2.0;
  b.speed_bins = 40;
  b.period = 0.2;
  b.phase_bins = 20;
  b.start_time = 0.3;
  b.end_time = 9.0;
  return b;
}

// Impacts [first, last) of one fixed pseudo-random sequence.
void feed(PairImpactHistogram& h, int first, int last) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < last; ++i) {
    const PairImpact im{10 * u(rng), 2.5 * u(rng), 0.01 * u(rng), u(rng) < 0.3};
    if (i >= first) h.pairImpact(im);
  }
}

}  // namespace

TEST(PairImpactHistogram, RestoredFromACheckpointItEndsAsAnUninterruptedOne) {
  granwave::testing::ScratchDir dir;
  PairImpactHistogram whole(phaseResolvedBins()), first(phaseResolvedBins());
  feed(whole, 0, 5000);
  feed(first, 0, 2000);
  {
    h5::File f = h5::File::create(dir.file("checkpoint.h5"));
    first.saveState(f, "/observers/pair_impacts");
  }
  PairImpactBins later = phaseResolvedBins();
  later.start_time = 1e300;  // a restarted run does not know the layer's steady start yet
  PairImpactHistogram resumed(later);
  resumed.restoreState(h5::File::openReadOnly(dir.file("checkpoint.h5")),
                       "/observers/pair_impacts");
  feed(resumed, 2000, 5000);
  EXPECT_GT(whole.total(), 1000u);
  EXPECT_EQ(resumed.total(), whole.total());
  EXPECT_EQ(resumed.counts(), whole.counts());
  EXPECT_EQ(resumed.bins().start_time, whole.bins().start_time);

  PairImpactBins other = phaseResolvedBins();
  other.speed_bins = 41;
  PairImpactHistogram wrong(other);
  EXPECT_THROW(wrong.restoreState(h5::File::openReadOnly(dir.file("checkpoint.h5")),
                                  "/observers/pair_impacts"),
               h5::H5Error);
}

TEST(PairImpactHistogram, RunFileKeepsTheHistogramAndItsBins) {
  granwave::testing::ScratchDir dir;
  PairImpactHistogram h(phaseResolvedBins());
  feed(h, 0, 3000);
  H5mdWriter writer(dir.file("run.h5"), "# scene\n", RunProvenance{"test", "", 1, "tester"},
                    BoxInfo{0.1, 0.1, 0.002, true, false}, 1);
  writer.writePairImpacts(h);
  EXPECT_THROW(writer.writePairImpacts(h), std::logic_error);
  writer.finish(true);
  const PairImpactHistogram back =
      PairImpactHistogram::read(h5::File::openReadOnly(dir.file("run.h5")), h5md::kPairImpacts);
  EXPECT_EQ(back.counts(), h.counts());
  EXPECT_EQ(back.total(), h.total());
  EXPECT_EQ(back.bins().phase_bins, 20);
  EXPECT_EQ(back.bins().speed_bins, 40);
  EXPECT_EQ(back.bins().period, 0.2);
  EXPECT_EQ(back.bins().start_time, 0.3);
  EXPECT_EQ(back.bins().end_time, 9.0);
  EXPECT_THROW(PairImpactHistogram::read(h5::File::openReadOnly(dir.file("run.h5")), "/nothing"),
               h5::H5Error);
}

TEST(PairImpactHistogram, ImpactsAfterEndTimeAreNotCounted) {
  PairImpactHistogram h(phaseResolvedBins());
  h.pairImpact({8.99, 0.5, 0.0, false});
  h.pairImpact({9.0, 0.5, 0.0, false});
  EXPECT_EQ(h.total(), 1u);
}
