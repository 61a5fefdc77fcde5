// The wave-fronts study's plan (studies/wave_fronts/WaveFrontsStudy.cpp): its N sweep sampled
// finely on a deep layer, which the fronts' transits through the layer's mass need.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "studies/wave_fronts/WaveFrontsStudy.hpp"
#include "tests/h5/ScratchDir.hpp"

using namespace granwave;

TEST(WaveFrontsPlan, FineSweepOfADeepLayerKeepsOneFrameOfPositionsPerCycle) {
  // The paper's scene file keeps positions at every phase: at 2000 phases per cycle its 15 s
  // of an N = 1200 layer (the hydro run's scene) would store 3.6e8 positions, beyond the limit
  // of 2.5e8. A study keeps one frame per cycle (stride 2000), so the plan is valid.
  granwave::testing::ScratchDir dir;
  const std::string root = GRANWAVE_SOURCE_DIR;
  const std::string path = (dir.path() / "deep.toml").string();
  std::ofstream(path) << "[study]\nkind = \"wave-fronts\"\n[scenes]\ndry = \"" << root
                      << "/scenes/paper-dry.toml\"\nwet = \"" << root
                      << "/scenes/paper-wet.toml\"\n[sweep]\nduration = 8.0\ncounts = [1200]\n"
                         "seeds = [1]\nphases_per_cycle = 2000\n[lammps]\nrun = \"no\"\n";
  StudyFile f = StudyFile::load(path);
  const std::unique_ptr<Study> study = makeWaveFrontsStudy(f);
  int sweep_runs = 0;
  for (const RunRequest& q : study->plan()) {
    if (q.kind != RunKind::Particles || q.scene.particles.count != 1200) continue;
    ++sweep_runs;
    EXPECT_EQ(q.scene.run.phases_per_cycle, 2000) << q.label;
    EXPECT_EQ(q.scene.run.trajectory_stride, 2000) << q.label;
  }
  EXPECT_EQ(sweep_runs, 2);  // dry and wet, one seed
}
