// One hydro run of a scene, driven directly: a scene without drive or without bottom and lid
// is refused with a line naming it, before any integration; a coarse run of the paper's dry
// scene holds whole cycles of the periodic state in the lab frame on the coarse-graining rows,
// its phases at t/T = k/M, its fronts among them, and reads back from its file as it was made.
#include <gtest/gtest.h>

#include <cmath>

#include "coarse_grain/FieldGrid.hpp"
#include "scene/SceneParser.hpp"
#include "studies/hydro_run/HydroRun.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

Scene paperDry(std::vector<std::string> overrides) {
  return parseSceneFile(std::string(GRANWAVE_SOURCE_DIR) + "/scenes/paper-dry.toml", overrides);
}

void expectRefused(const Scene& s, const std::string& why) {
  try {
    runHydroScene(s, "scene.toml", nullptr);
    ADD_FAILURE() << "not refused";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("scene.toml: granwave hydro needs " + why, 0), 0u)
        << e.what();
  }
}

}  // namespace

TEST(HydroRun, SceneWithoutDriveOrWithoutWallsIsRefusedNamingIt) {
  expectRefused(paperDry({"drive.frequency=0"}), "a driven scene");
  // Not a scene the parser lets through driven, but the guard holds on its own.
  Scene periodic = paperDry({});
  periodic.container.periodic_z = true;
  expectRefused(periodic, "bottom and lid");
}

TEST(HydroRun, CoarseRunHoldsWholeCyclesOnTheLabRowsAndReadsBackAsMade) {
  const Scene s = paperDry({"hydro.cells=100", "run.phases_per_cycle=50", "run.duration=1.2"});
  const HydroRunContent c = runHydroScene(s, "paper-dry.toml", nullptr);
  ASSERT_TRUE(c.periodic);
  const PhaseProfiles& lab = c.lab;
  const int M = 50;
  ASSERT_EQ(lab.phases(), c.windowCycles() * M);
  for (int k = 0; k < lab.phases(); ++k)
    EXPECT_NEAR(lab.phase[static_cast<std::size_t>(k)], static_cast<double>(k + 1) / M, 1e-12);
  const SceneDerived dv = derive(s);
  const FieldGrid grid = FieldGrid::forContainer(s.container.width, s.container.height,
                                                 dv.amplitude, s.particles.diameter);
  ASSERT_EQ(lab.rows(), grid.nz);
  EXPECT_EQ(lab.z.front(), grid.zCentre(0));
  EXPECT_EQ(c.plate_z.size(), static_cast<std::size_t>(lab.phases()) * 100);
  for (const FrontEpisode& e : lab.fronts) {
    EXPECT_GE(e.first_phase, 0);
    EXPECT_LT(e.first_phase, lab.phases());
  }
  testing::ScratchDir dir;
  writeHydroRunFile(dir.file("h.h5"), c);
  const HydroRunContent r = readHydroRunFile(dir.file("h.h5"));
  EXPECT_EQ(r.lab.phase, lab.phase);
  EXPECT_EQ(r.lab.z, lab.z);
  EXPECT_EQ(r.lab.fronts.size(), lab.fronts.size());
  EXPECT_EQ(r.steps, c.steps);
}

}  // namespace granwave
