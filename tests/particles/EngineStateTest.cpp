// Checkpoint support of the engine: a run paused, saved (in memory or through the HDF5
// archive) and continued in a new engine ends bit-identical to the run that never stopped,
// on the scenes that exercise every kind of state: the wet paper layer with friction, TC
// and particles riding the plate, and a periodic gas with its virial pressure.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "EngineTestSupport.hpp"
#include "h5/File.hpp"
#include "h5/H5Error.hpp"
#include "particles/StateArchive.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

using ::testing::HasSubstr;

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Every record of a run, for comparing whole histories bit for bit.
struct History : SnapshotObserver {
  std::vector<Snapshot> records;
  void observe(const Snapshot& s) override { records.push_back(s); }
};

void expectSameRecords(const std::vector<Snapshot>& a, const std::vector<Snapshot>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    SCOPED_TRACE("record " + std::to_string(k));
    EXPECT_EQ(a[k].step, b[k].step);
    EXPECT_TRUE(sameBits(a[k].time, b[k].time));
    EXPECT_TRUE(sameBits(a[k].x, b[k].x));
    EXPECT_TRUE(sameBits(a[k].z, b[k].z));
    EXPECT_TRUE(sameBits(a[k].vx, b[k].vx));
    EXPECT_TRUE(sameBits(a[k].vz, b[k].vz));
    EXPECT_TRUE(sameBits(a[k].omega, b[k].omega));
    EXPECT_TRUE(sameBits(a[k].obs.dissipated_energy, b[k].obs.dissipated_energy));
    EXPECT_TRUE(sameBits(a[k].obs.wall_work, b[k].obs.wall_work));
    EXPECT_TRUE(sameBits(a[k].obs.pressure, b[k].obs.pressure));
    EXPECT_EQ(a[k].obs.events, b[k].obs.events);
    EXPECT_EQ(a[k].obs.collisions.tc_elastic, b[k].obs.collisions.tc_elastic);
    EXPECT_EQ(a[k].obs.collisions.rests, b[k].obs.collisions.rests);
    if (::testing::Test::HasFailure()) return;
  }
}

// The whole run without a stop.
std::vector<Snapshot> uninterrupted(const Scene& s) {
  EdSimulation sim = test::makeSimulation(s);
  History h;
  sim.addObserver(&h);
  EXPECT_TRUE(sim.run().completed);
  return h.records;
}

// Paused after `pause_after` records, its state handed to `transfer`, continued in a new
// engine built from what `transfer` returns.
template <class Transfer>
std::vector<Snapshot> restarted(const Scene& s, int pause_after, Transfer transfer) {
  const EngineConfig c = engineConfig(s);
  History h;
  EdSimulation first(c, initialCondition(s, c));
  first.addObserver(&h);
  int seen = 0;
  const RunStatus paused = first.run(nullptr, [&] { return ++seen == pause_after; });
  EXPECT_TRUE(paused.paused);
  EXPECT_FALSE(paused.completed);
  EdSimulation second(c, transfer(first.state()));
  second.addObserver(&h);
  EXPECT_TRUE(second.run().completed);
  return h.records;
}

Scene wetPaperLayer() {
  Scene s = test::paperScene(RestitutionKind::Wet, 0.6);
  s.run.phases_per_cycle = 50;
  return s;
}

Scene periodicGas() {
  Scene s = test::periodicGas(200, 0.3, 1e-6, 0.9);
  s.run.duration = 0.2;
  s.run.record_interval = 0.01;
  return s;
}

TEST(EngineState, RestartFromStateContinuesBitIdenticalForWetPaperLayer) {
  const Scene s = wetPaperLayer();
  const auto whole = uninterrupted(s);
  // Records 17 (the layer in flight) and 49 (the layer on the plate, 15 particles riding it):
  // the riding particles' offsets and motion flags must survive the restart too.
  for (const auto& [pause_after, riders] : {std::pair{17, false}, std::pair{49, true}}) {
    SCOPED_TRACE("pause after record " + std::to_string(pause_after));
    long riding = -1;
    expectSameRecords(whole, restarted(s, pause_after, [&riding](EngineState st) {
                        riding = std::count_if(
                            st.particles.begin(), st.particles.end(),
                            [](const ParticleState& p) { return p.motion != Motion::Ballistic; });
                        return st;
                      }));
    if (riders)
      EXPECT_GT(riding, 0);
    else
      EXPECT_EQ(riding, 0);
  }
}

TEST(EngineState, RestartThroughHdf5ArchiveContinuesBitIdentical) {
  testing::ScratchDir dir;
  for (const Scene& s : {wetPaperLayer(), periodicGas()}) {
    const auto whole = uninterrupted(s);
    const auto continued = restarted(s, 9, [&](const EngineState& st) {
      {
        h5::File f = h5::File::create(dir.file("state.h5"));
        writeEngineState(f, "/engine", st);
      }
      return readEngineState(h5::File::openReadOnly(dir.file("state.h5")), "/engine");
    });
    expectSameRecords(whole, continued);
  }
}

TEST(EngineState, PauseAndContinueInOneEngineChangesNothing) {
  const Scene s = wetPaperLayer();
  const auto whole = uninterrupted(s);
  EdSimulation sim = test::makeSimulation(s);
  History h;
  sim.addObserver(&h);
  int calls = 0, pauses = 0;
  RunStatus st;
  do {
    st = sim.run(nullptr, [&] { return ++calls % 7 == 0; });
    if (st.paused) ++pauses;
  } while (!st.completed);
  EXPECT_GT(pauses, 3);
  expectSameRecords(whole, h.records);
}

TEST(EngineState, StateOfAnotherSizeOrBrokenQueueIsRefused) {
  const Scene s = wetPaperLayer();
  const EngineConfig c = engineConfig(s);
  EdSimulation sim(c, initialCondition(s, c));
  sim.advanceTo(0.05);
  const EngineState good = sim.state();

  EngineState fewer_events = good;
  fewer_events.events.pop_back();
  EXPECT_THROW(EdSimulation(c, fewer_events), std::invalid_argument);

  EngineState not_a_heap = good;
  std::swap(not_a_heap.queue.keys.front(), not_a_heap.queue.keys.back());
  EXPECT_THROW(EdSimulation(c, not_a_heap), std::invalid_argument);

  EngineState unlinked = good;
  unlinked.cells.cell[0] =
      (unlinked.cells.cell[0] + 1) % static_cast<int>(unlinked.cells.head.size());
  EXPECT_THROW(EdSimulation(c, unlinked), std::invalid_argument);

  Scene wider = s;
  wider.container.width *= 2;
  const EngineConfig cw = engineConfig(wider);
  EXPECT_THROW(EdSimulation(cw, good), std::invalid_argument);  // another cell grid
}

TEST(StateArchive, SnapshotsRoundTripBitExactly) {
  testing::ScratchDir dir;
  EdSimulation sim = test::makeSimulation(wetPaperLayer());
  std::vector<Snapshot> saved;
  for (double t : {0.01, 0.02, 0.035}) {
    sim.advanceTo(t);
    saved.push_back(sim.snapshot());
  }
  {
    h5::File f = h5::File::create(dir.file("snapshots.h5"));
    writeSnapshots(f, "/kept", saved);
    writeSnapshots(f, "/none", {});
  }
  const h5::File f = h5::File::openReadOnly(dir.file("snapshots.h5"));
  expectSameRecords(saved, readSnapshots(f, "/kept"));
  EXPECT_TRUE(readSnapshots(f, "/none").empty());
}

TEST(StateArchive, MissingDatasetIsNamed) {
  testing::ScratchDir dir;
  EdSimulation sim = test::makeSimulation(wetPaperLayer());
  {
    h5::File f = h5::File::create(dir.file("state.h5"));
    writeEngineState(f, "/engine", sim.state());
    H5Ldelete(f.id(), "/engine/cell_prev", H5P_DEFAULT);
  }
  try {
    readEngineState(h5::File::openReadOnly(dir.file("state.h5")), "/engine");
    FAIL() << "a state without its cell lists was read";
  } catch (const h5::H5Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("cell_prev"));
  }
}

}  // namespace
}  // namespace granwave
