// What the studies read of a particle run file, through the H5MD reader: the observables of
// every record with the counters at the end, and the last trajectory frame with the plate
// height of its record, on a run file of known records.
#include <gtest/gtest.h>

#include "particles/H5mdWriter.hpp"
#include "studies/run_files/RunOutputs.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

// Five records, two particles, every second record a trajectory frame (steps 0, 2, 4).
std::string runFile(const testing::ScratchDir& dir) {
  const std::string path = dir.file("run.h5");
  H5mdWriter w(path, "[run]\n", RunProvenance{"test", "test", 1, "test"},
               BoxInfo{0.06, 0.04, 0.002, false, false}, 2);
  for (int k = 0; k < 5; ++k) {
    Snapshot s;
    s.step = static_cast<std::uint64_t>(k);
    s.time = 0.01 * k;
    s.plate_height = 1e-4 * k;
    s.x = {0.01 + k * 1e-3, 0.02};
    s.z = {0.003, 0.004 + k * 1e-3};
    s.vx = s.vz = s.omega = {0.0, 0.0};
    s.obs.center_of_mass_height = 0.003 + 1e-4 * k;
    s.obs.kinetic_energy = 1e-6 * (k + 1);
    s.obs.dissipated_energy = 3e-6 * k;
    s.obs.pair_impact_energy = 2e-6 * k;
    s.obs.pair_impact_loss = 1e-6 * k;
    s.obs.collisions = {10u * k, 3u * k, 2u * k, 0};
    s.obs.events = 100u * k;
    w.observe(s);
  }
  w.finish(true);
  return path;
}

}  // namespace

TEST(RunOutputs, ObservablesAreEveryRecordsAndTheCountersAtTheEnd) {
  testing::ScratchDir dir;
  const RunObservables o = readRunObservables(runFile(dir));
  ASSERT_EQ(o.time.size(), 5u);
  EXPECT_EQ(o.time[3], 0.03);
  EXPECT_EQ(o.com_height[4], 0.003 + 1e-4 * 4);
  EXPECT_EQ(o.kinetic_energy[0], 1e-6);
  EXPECT_EQ(o.dissipated_energy[4], 12e-6);
  EXPECT_EQ(o.pair_impact_energy[2], 4e-6);
  EXPECT_EQ(o.pair_impact_loss[2], 2e-6);
  EXPECT_EQ(o.pair_count, (std::vector<double>{0, 10, 20, 30, 40}));
  EXPECT_EQ(o.tc_elastic_count, (std::vector<double>{0, 2, 4, 6, 8}));
  EXPECT_EQ(o.events, 400u);
  EXPECT_EQ(o.pair_collisions, 40u);
  EXPECT_EQ(o.wall_collisions, 12u);
  EXPECT_EQ(o.tc_elastic, 8u);
}

TEST(RunOutputs, LastFrameIsTheLastTrajectoryRecordWithItsPlate) {
  testing::ScratchDir dir;
  const Frame f = readLastFrame(runFile(dir));
  EXPECT_EQ(f.x, (std::vector<double>{0.01 + 4 * 1e-3, 0.02}));
  EXPECT_EQ(f.z, (std::vector<double>{0.003, 0.004 + 4 * 1e-3}));
  EXPECT_EQ(f.plate, 1e-4 * 4);
}

}  // namespace granwave
