// H5mdWriter + H5mdReader: a run written as H5MD reads back bit-exactly, carries the H5MD
// header standard tools look for, and anything that is not a finished granwave run is
// refused with a one-line message naming the file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "h5/H5Error.hpp"
#include "particles/H5mdReader.hpp"
#include "particles/H5mdWriter.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr int kParticles = 7;
constexpr int kSnapshots = 5;
constexpr int kStride = 2;

const std::string kScene =
    "# vibrated layer\n[particles]\ncount = 7\ndiameter = 0.002\n\n[container]\n"
    "periodic_x = true\nname = \"Ω \\\"quoted\\\"\"\n";

const BoxInfo kBox{0.06, 0.05, 0.002, true, false};

// Deterministic snapshots with awkward values (subnormals, -0, huge) so that "bit-exact"
// means something.
std::vector<Snapshot> makeSnapshots() {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Snapshot> snapshots;
  for (int k = 0; k < kSnapshots; ++k) {
    Snapshot s;
    s.step = static_cast<std::uint64_t>(k);
    s.time = 0.01 * k + 1e-17;
    s.plate_height = 1e-4 * uniform(rng);
    for (int j = 0; j < kParticles; ++j) {
      s.x.push_back(0.06 * std::abs(uniform(rng)));
      s.z.push_back(0.05 * std::abs(uniform(rng)));
      s.vx.push_back(uniform(rng));
      s.vz.push_back(j == 0 ? -0.0 : uniform(rng));
      s.omega.push_back(j == 1 ? 4.9e-324 : 1e3 * uniform(rng));
    }
    s.obs.center_of_mass_height = uniform(rng);
    s.obs.kinetic_energy = uniform(rng);
    s.obs.rotational_energy = uniform(rng);
    s.obs.potential_energy = uniform(rng);
    s.obs.dissipated_energy = uniform(rng);
    s.obs.wall_work = uniform(rng);
    s.obs.pressure = 1e300 * uniform(rng);
    s.obs.collisions = {rng(), rng(), rng(), 1u + k};
    s.obs.events = rng();
    snapshots.push_back(s);
  }
  return snapshots;
}

RunProvenance makeProvenance() {
  return {"0.1.0-test", "granwave simulate scene.toml --set run.seed=99", 99, "tester"};
}

void writeRun(const std::string& path, const std::vector<Snapshot>& snapshots, bool complete = true,
              const std::string& summary = "", const std::string& override_path = "") {
  H5mdWriter writer(path, kScene, makeProvenance(), kBox, kStride);
  for (const Snapshot& s : snapshots) writer.observe(s);
  writer.finish(complete, summary, override_path);
}

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

void expectBitEqual(const std::vector<double>& a, const std::vector<double>& b,
                    const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(bits(a[i]), bits(b[i])) << what << i;
}

void expectSameSnapshot(const Snapshot& a, const Snapshot& b) {
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(bits(a.time), bits(b.time));
  EXPECT_EQ(bits(a.plate_height), bits(b.plate_height));
  expectBitEqual(a.x, b.x, "x");
  expectBitEqual(a.z, b.z, "z");
  expectBitEqual(a.vx, b.vx, "vx");
  expectBitEqual(a.vz, b.vz, "vz");
  expectBitEqual(a.omega, b.omega, "omega");
  for (const auto& o : h5md::kRealObservables) {
    EXPECT_EQ(bits(o.get(a)), bits(o.get(b))) << o.name;
  }
  for (const auto& o : h5md::kCountObservables) EXPECT_EQ(o.get(a), o.get(b)) << o.name;
  for (const auto& o : h5md::kCollisionColumns) EXPECT_EQ(o.get(a), o.get(b)) << o.name;
}

template <class Action>
std::string h5ErrorOf(Action action) {
  try {
    action();
  } catch (const h5::H5Error& error) {
    return error.what();
  }
  ADD_FAILURE() << "no H5Error thrown";
  return {};
}

TEST(H5mdWriter, RoundTripIsBitExact) {
  testing::ScratchDir dir;
  const std::string path = dir.file("RUN.h5");
  const std::vector<Snapshot> snapshots = makeSnapshots();
  writeRun(path, snapshots, true, "5 records");

  const H5mdReader run(path);
  EXPECT_TRUE(run.completed());
  EXPECT_EQ(run.summary(), "5 records");
  EXPECT_EQ(run.recordCount(), 5u);
  ASSERT_EQ(run.frameCount(), 3u);  // steps 0, 2, 4
  EXPECT_EQ(run.particleCount(), kParticles);
  for (std::size_t i = 0; i < run.frameCount(); ++i) {
    SCOPED_TRACE("frame " + std::to_string(i));
    expectSameSnapshot(run.frame(i), snapshots[kStride * i]);
  }
  EXPECT_THROW(run.frame(3), std::out_of_range);

  for (const auto& o : h5md::kRealObservables) {
    const TimeSeries series = run.observable(o.name);
    ASSERT_EQ(series.value.size(), snapshots.size()) << o.name;
    for (std::size_t k = 0; k < snapshots.size(); ++k) {
      EXPECT_EQ(series.step[k], static_cast<std::int64_t>(k));
      EXPECT_EQ(bits(series.time[k]), bits(snapshots[k].time));
      EXPECT_EQ(bits(series.value[k]), bits(o.get(snapshots[k]))) << o.name;
    }
  }
  const TimeSeries rests = run.observable("collisions/rests");
  ASSERT_EQ(rests.value.size(), snapshots.size());
  for (std::size_t k = 0; k < snapshots.size(); ++k) {
    EXPECT_EQ(rests.value[k], static_cast<double>(snapshots[k].obs.collisions.rests));
    EXPECT_EQ(rests.step[k], static_cast<std::int64_t>(k));
  }
  EXPECT_THROW(run.observable("collisions/other"), h5::H5Error);
  EXPECT_THROW(run.observable("no_such_observable"), h5::H5Error);

  // Counters exactly, through the raw table (TimeSeries holds doubles).
  const h5::File file = h5::File::openReadOnly(path);
  EXPECT_EQ(file.readStringArrayAttribute("/observables/collisions/value", "columns"),
            (std::vector<std::string>{"pair", "wall", "tc_elastic", "rests"}));
  const std::vector<std::uint64_t> table =
      file.readDataset<std::uint64_t>("/observables/collisions/value", {5, 4});
  for (std::size_t k = 0; k < snapshots.size(); ++k) {
    const CollisionCounts& c = snapshots[k].obs.collisions;
    EXPECT_EQ(table[4 * k], c.pair);
    EXPECT_EQ(table[4 * k + 1], c.wall);
    EXPECT_EQ(table[4 * k + 2], c.tc_elastic);
    EXPECT_EQ(table[4 * k + 3], c.rests);
  }
}

TEST(H5mdWriter, BoxProvenanceAndSceneRoundTrip) {
  testing::ScratchDir dir;
  const std::string path = dir.file("RUN.h5");
  writeRun(path, makeSnapshots());
  const H5mdReader run(path);
  EXPECT_EQ(run.sceneToml(), kScene);
  EXPECT_EQ(run.box().width, kBox.width);
  EXPECT_EQ(run.box().height, kBox.height);
  EXPECT_EQ(run.box().thickness, kBox.thickness);
  EXPECT_TRUE(run.box().periodic_x);
  EXPECT_FALSE(run.box().periodic_z);
  EXPECT_EQ(run.provenance().program_version, "0.1.0-test");
  EXPECT_EQ(run.provenance().command_line, "granwave simulate scene.toml --set run.seed=99");
  EXPECT_EQ(run.provenance().seed, 99u);
  EXPECT_EQ(run.provenance().author, "tester");
}

TEST(H5mdWriter, WritesTheH5mdHeaderToolsExpect) {
  testing::ScratchDir dir;
  const std::string path = dir.file("RUN.h5");
  writeRun(path, makeSnapshots());
  const h5::File file = h5::File::openReadOnly(path);
  EXPECT_EQ(file.readArrayAttribute<std::int64_t>("/h5md", "version"),
            (std::vector<std::int64_t>{1, 1}));
  EXPECT_EQ(file.readStringAttribute("/h5md/creator", "name"), "granwave");
  EXPECT_EQ(file.readStringAttribute("/h5md/creator", "version"), "0.1.0-test");
  EXPECT_EQ(file.readStringAttribute("/h5md/author", "name"), "tester");
  EXPECT_EQ(file.readAttribute<std::int64_t>("/particles/all/box", "dimension"), 3);
  EXPECT_EQ(file.readStringArrayAttribute("/particles/all/box", "boundary"),
            (std::vector<std::string>{"periodic", "none", "none"}));
  EXPECT_EQ(file.readDataset<double>("/particles/all/box/edges/value", {3, 3, 3}),
            (std::vector<double>{0.06, 0, 0, 0,    0.002, 0, 0, 0, 0.05,  0.06, 0, 0, 0,   0.002,
                                 0,    0, 0, 0.05, 0.06,  0, 0, 0, 0.002, 0,    0, 0, 0.05}));
  EXPECT_EQ(file.shape("/particles/all/position/value"), (h5::Shape{3, kParticles, 3}));
  EXPECT_EQ(file.readDataset<std::int64_t>("/particles/all/velocity/step"),
            (std::vector<std::int64_t>{0, 2, 4}));
  EXPECT_EQ(file.readAttribute<std::int64_t>("/parameters", "completed"), 1);
  const std::vector<std::pair<std::string, std::string>> units{
      {"/particles/all/position/value", "m"},
      {"/particles/all/velocity/value", "m s-1"},
      {"/particles/all/angular_velocity/value", "rad s-1"},
      {"/particles/all/box/edges/value", "m"},
      {"/particles/all/position/time", "s"},
      {"/observables/kinetic_energy/value", "J"},
      {"/observables/pressure/value", "Pa m"},
      {"/observables/plate_height/value", "m"},
      {"/observables/events/value", "1"},
      {"/observables/collisions/value", "1"}};
  for (const auto& [dataset, unit] : units) {
    EXPECT_EQ(file.readStringAttribute(dataset, "unit"), unit) << dataset;
  }
}

TEST(H5mdWriter, H5lsListsThePositions) {
  if (std::system("command -v h5ls > /dev/null 2>&1") != 0) GTEST_SKIP() << "no h5ls";
  testing::ScratchDir dir;
  const std::string path = dir.file("RUN.h5");
  const std::string listing = dir.file("listing.txt");
  writeRun(path, makeSnapshots());
  ASSERT_EQ(std::system(("h5ls -r '" + path + "' > '" + listing + "' 2>&1").c_str()), 0);
  std::ifstream in(listing);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(text, HasSubstr("/particles/all/position/value Dataset {3/Inf, 7, 3}"));
  EXPECT_THAT(text, HasSubstr("/observables/collisions/value Dataset {5/Inf, 4}"));
}

TEST(H5mdWriter, UnfinishedRunLeavesNothing) {
  testing::ScratchDir dir;
  const std::string path = dir.file("RUN.h5");
  const std::vector<Snapshot> snapshots = makeSnapshots();
  {
    H5mdWriter writer(path, kScene, makeProvenance(), kBox, kStride);
    writer.observe(snapshots[0]);
    writer.observe(snapshots[1]);
  }
  EXPECT_TRUE(dir.empty());
}

TEST(H5mdWriter, InterruptedRunIsSavedAsideAndMarkedIncomplete) {
  testing::ScratchDir dir;
  const std::string path = dir.file("RUN.h5");
  std::vector<Snapshot> snapshots = makeSnapshots();
  snapshots.resize(3);
  writeRun(path, snapshots, false, "interrupted at t = 0.02 s", path + ".interrupted");
  EXPECT_FALSE(fs::exists(path));
  const H5mdReader run(path + ".interrupted");
  EXPECT_FALSE(run.completed());
  EXPECT_EQ(run.summary(), "interrupted at t = 0.02 s");
  EXPECT_EQ(run.recordCount(), 3u);
  EXPECT_EQ(run.frameCount(), 2u);
  expectSameSnapshot(run.frame(1), snapshots[2]);
}

TEST(H5mdWriter, RunsWithoutFramesStayReadable) {
  testing::ScratchDir dir;
  const std::string empty = dir.file("empty.h5");
  H5mdWriter(empty, kScene, makeProvenance(), kBox, kStride).finish(false, "stopped at once");
  const H5mdReader none(empty);
  EXPECT_EQ(none.frameCount(), 0u);
  EXPECT_EQ(none.recordCount(), 0u);
  EXPECT_EQ(none.particleCount(), 0);
  EXPECT_FALSE(none.completed());

  const std::string offStride = dir.file("off_stride.h5");
  Snapshot odd = makeSnapshots()[1];  // step 1: a record, not a frame
  {
    H5mdWriter writer(offStride, kScene, makeProvenance(), kBox, kStride);
    writer.observe(odd);
    writer.finish(true);
  }
  const H5mdReader one(offStride);
  EXPECT_EQ(one.frameCount(), 0u);
  EXPECT_EQ(one.recordCount(), 1u);
  EXPECT_EQ(one.particleCount(), kParticles);
  EXPECT_EQ(one.observable("kinetic_energy").value, std::vector<double>{odd.obs.kinetic_energy});
}

TEST(H5mdWriter, InconsistentSnapshotsAreRejected) {
  testing::ScratchDir dir;
  const std::string path = dir.file("RUN.h5");
  std::vector<Snapshot> snapshots = makeSnapshots();
  H5mdWriter writer(path, kScene, makeProvenance(), kBox, kStride);
  writer.observe(snapshots[0]);
  snapshots[1].x.push_back(0.0);
  EXPECT_THROW(writer.observe(snapshots[1]), std::invalid_argument);
  snapshots[2].vz.pop_back();
  EXPECT_THROW(writer.observe(snapshots[2]), std::invalid_argument);
  EXPECT_THROW(H5mdWriter(dir.file("other.h5"), kScene, makeProvenance(), kBox, 0),
               std::invalid_argument);
}

TEST(H5mdReader, ForeignHdf5FileIsRejected) {
  testing::ScratchDir dir;
  const std::string path = dir.file("foreign.h5");
  {
    hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    hid_t group = H5Gcreate2(file, "/particles", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Gclose(group);
    H5Fclose(file);
  }
  EXPECT_EQ(h5ErrorOf([&] { H5mdReader run(path); }), path + ": not an H5MD file (no /h5md group)");
}

TEST(H5mdReader, H5mdFromAnotherProgramIsRejected) {
  testing::ScratchDir dir;
  const std::string path = dir.file("lammps.h5");
  {
    h5::File file = h5::File::create(path);
    file.createGroup("/h5md/creator");
    file.writeArrayAttribute<std::int64_t>("/h5md", "version", {1, 1});
    file.writeStringAttribute("/h5md/creator", "name", "LAMMPS");
    file.close();
  }
  EXPECT_EQ(h5ErrorOf([&] { H5mdReader run(path); }),
            path + ": H5MD file written by 'LAMMPS', not by granwave");
}

TEST(H5mdReader, MissingDatasetIsNamed) {
  testing::ScratchDir dir;
  const std::string path = dir.file("RUN.h5");
  writeRun(path, makeSnapshots());
  {
    hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Ldelete(file, "/particles/all/position/value", H5P_DEFAULT);
    H5Fclose(file);
  }
  EXPECT_EQ(h5ErrorOf([&] { H5mdReader run(path); }),
            path + ": no dataset /particles/all/position/value (not a granwave run?)");
}

TEST(H5mdReader, InconsistentShapesAreNamed) {
  testing::ScratchDir dir;
  const std::string path = dir.file("RUN.h5");
  writeRun(path, makeSnapshots());
  {
    // One velocity frame fewer than positions.
    hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    hid_t dataset = H5Dopen2(file, "/particles/all/velocity/value", H5P_DEFAULT);
    const hsize_t extent[] = {2, kParticles, 3};
    H5Dset_extent(dataset, extent);
    H5Dclose(dataset);
    H5Fclose(file);
  }
  EXPECT_THAT(h5ErrorOf([&] { H5mdReader run(path); }),
              AllOf(HasSubstr(path + ": "), HasSubstr("/particles/all/velocity")));
}

TEST(H5mdReader, NotHdf5AndMissingFilesAreNamed) {
  testing::ScratchDir dir;
  const std::string text = dir.file("scene.toml");
  std::ofstream(text) << kScene;
  EXPECT_EQ(h5ErrorOf([&] { H5mdReader run(text); }), text + ": not an HDF5 file");
  const std::string absent = dir.file("absent.h5");
  EXPECT_EQ(h5ErrorOf([&] { H5mdReader run(absent); }), absent + ": no such file");
}

TEST(H5mdReader, TruncatedRunIsAnError) {
  testing::ScratchDir dir;
  const std::string path = dir.file("RUN.h5");
  writeRun(path, makeSnapshots());
  fs::resize_file(path, fs::file_size(path) / 2);
  EXPECT_THAT(h5ErrorOf([&] {
                H5mdReader run(path);
                for (std::size_t i = 0; i < run.frameCount(); ++i) (void)run.frame(i);
              }),
              HasSubstr(path + ": "));
}

}  // namespace
}  // namespace granwave
