// The accumulating observers saved mid-run and restored into fresh ones end exactly as the
// observers that saw the whole run: the phase averager (sums, steady-state detection, block
// bookkeeping) and the pattern sampler (the kept cycles), on synthetic snapshots.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "coarse_grain/PatternSampler.hpp"
#include "coarse_grain/PhaseAverager.hpp"
#include "h5/File.hpp"
#include "h5/H5Error.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

constexpr int kRecordsPerCycle = 10, kCycles = 40, kParticles = 60;

// A layer whose mean height relaxes over the first cycles (so the steady-state detector has
// something to decide) and then breathes with the drive.
std::vector<Snapshot> syntheticRun() {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(0.0, 0.02), jitter(-0.001, 0.001), v(-0.1, 0.1);
  std::vector<Snapshot> run;
  for (int k = 0; k < kRecordsPerCycle * kCycles; ++k) {
    Snapshot s;
    s.step = static_cast<std::uint64_t>(k);
    s.time = 0.01 * k;
    const double cycle = static_cast<double>(k) / kRecordsPerCycle;
    const double mean = 0.004 + 0.006 * std::exp(-cycle / 3.0) + 0.002 * std::sin(2 * M_PI * cycle);
    for (int i = 0; i < kParticles; ++i) {
      s.x.push_back(x(rng));
      s.z.push_back(mean + jitter(rng));
      s.vx.push_back(v(rng));
      s.vz.push_back(v(rng));
      s.omega.push_back(v(rng));
    }
    s.obs.center_of_mass_height = mean;
    // Cumulative energies that grow unevenly over a cycle (the budget the averager pools).
    const double grown = k + 0.5 * std::sin(2 * M_PI * cycle);
    s.obs.wall_work = 1e-3 * grown;
    s.obs.dissipated_energy = 0.9e-3 * grown;
    s.obs.wall_dissipated_energy = 0.1e-3 * grown;
    run.push_back(std::move(s));
  }
  return run;
}

PhaseAveragerConfig averagerConfig() {
  PhaseAveragerConfig c;
  c.grid.nx = 10;
  c.grid.nz = 10;
  c.grid.wx = c.grid.wz = 0.002;
  c.samples_per_cycle = kRecordsPerCycle;
  c.cycles_per_window = 2;
  c.blocks = 4;
  c.total_cycles = kCycles;
  return c;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Feeds `observer` the whole run, or the run in two halves with a save to HDF5 and a restore
// into a new observer in between; returns the observer that saw the end.
template <class Observer, class Make>
std::unique_ptr<Observer> observe(const std::vector<Snapshot>& run, Make make, int stop_at,
                                  const std::string& file) {
  auto first = make();
  for (int k = 0; k < static_cast<int>(run.size()); ++k) {
    if (k == stop_at) {
      {
        h5::File f = h5::File::create(file);
        first->saveState(f, "/observer");
      }
      auto second = make();
      second->restoreState(h5::File::openReadOnly(file), "/observer");
      first = std::move(second);
    }
    first->observe(run[k]);
  }
  return first;
}

TEST(CheckpointedObservers, RestoredPhaseAveragerEndsAsTheUninterruptedOne) {
  testing::ScratchDir dir;
  const auto run = syntheticRun();
  auto make = [] { return std::make_unique<PhaseAverager>(averagerConfig()); };
  const auto whole = observe<PhaseAverager>(run, make, -1, dir.file("a.h5"));
  ASSERT_GE(whole->firstPooledCycle(), 5);  // the detector had a decision to make
  // Before the steady state is detected, right after it, and mid-way through a cycle.
  for (int stop_at : {33, 127, 255}) {
    SCOPED_TRACE("saved before record " + std::to_string(stop_at));
    const auto resumed = observe<PhaseAverager>(run, make, stop_at, dir.file("a.h5"));
    EXPECT_EQ(resumed->firstPooledCycle(), whole->firstPooledCycle());
    EXPECT_EQ(resumed->pooledCycles(), whole->pooledCycles());
    const PhaseAccumulator &a = whole->accumulator(), &b = resumed->accumulator();
    int differing = 0;
    for (int block = 0; block < a.blocks(); ++block)
      for (int phase = 0; phase < a.phases(); ++phase) {
        differing += !sameBits(a.snapshots(block, phase), b.snapshots(block, phase));
        for (int t = 0; t < PhaseAccumulator::kBudgetTerms; ++t)
          differing += !sameBits(a.budget(block, phase, t), b.budget(block, phase, t));
        for (int cell = 0; cell < a.grid().cells(); ++cell) {
          const CellSums &p = a.at(block, phase, cell), &q = b.at(block, phase, cell);
          differing += std::memcmp(&p, &q, sizeof p) != 0;
        }
      }
    EXPECT_EQ(differing, 0);
    EXPECT_TRUE(b.hasBudget());
  }
}

// Every field of two snapshots agrees bit for bit.
void expectSameBits(const Snapshot& p, const Snapshot& q) {
  EXPECT_EQ(p.step, q.step);
  EXPECT_TRUE(sameBits(p.time, q.time));
  EXPECT_TRUE(sameBits(p.plate_height, q.plate_height));
  EXPECT_TRUE(sameBits(p.obs.center_of_mass_height, q.obs.center_of_mass_height));
  for (const auto member :
       {&Snapshot::x, &Snapshot::z, &Snapshot::vx, &Snapshot::vz, &Snapshot::omega}) {
    ASSERT_EQ((p.*member).size(), static_cast<std::size_t>(kParticles));
    ASSERT_EQ((q.*member).size(), static_cast<std::size_t>(kParticles));
    EXPECT_EQ(0, std::memcmp((p.*member).data(), (q.*member).data(), kParticles * sizeof(double)));
  }
}

TEST(CheckpointedObservers, RestoredPatternSamplerKeepsTheSameCycles) {
  testing::ScratchDir dir;
  const auto run = syntheticRun();
  auto make = [] {
    return std::make_unique<PatternSampler>(PatternSamplerConfig{kRecordsPerCycle, 5, 8});
  };
  const auto whole = observe<PatternSampler>(run, make, -1, dir.file("p.h5"));
  const auto resumed = observe<PatternSampler>(run, make, 301, dir.file("p.h5"));
  const auto a = whole->cycles(), b = resumed->cycles();
  ASSERT_EQ(a.size(), 8u);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t c = 0; c < a.size(); ++c) {
    ASSERT_EQ(a[c].size(), b[c].size());
    for (std::size_t k = 0; k < a[c].size(); ++k) expectSameBits(a[c][k], b[c][k]);
  }
}

TEST(CheckpointedObservers, AveragerStateOfAnotherGridIsRefused) {
  testing::ScratchDir dir;
  PhaseAverager saved(averagerConfig());
  for (const Snapshot& s : syntheticRun()) saved.observe(s);
  {
    h5::File f = h5::File::create(dir.file("a.h5"));
    saved.saveState(f, "/observer");
  }
  PhaseAveragerConfig other = averagerConfig();
  other.grid.nx = 12;
  PhaseAverager restored(other);
  EXPECT_THROW(restored.restoreState(h5::File::openReadOnly(dir.file("a.h5")), "/observer"),
               h5::H5Error);
}

}  // namespace
}  // namespace granwave
