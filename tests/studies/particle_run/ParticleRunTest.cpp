// One particle run as `granwave simulate` makes it, driven directly: a short run of the paper's
// dry scene ends in a completed run file that names the program and command that made it, and
// an output that would overwrite the scene is refused before any work, the scene untouched.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "files/OutputPath.hpp"
#include "particles/H5mdReader.hpp"
#include "scene/SceneDerived.hpp"
#include "scene/SceneParser.hpp"
#include "studies/particle_run/ParticleRun.hpp"
#include "studies/runner/ExitCode.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

const std::string kScene = std::string(GRANWAVE_SOURCE_DIR) + "/scenes/paper-dry.toml";

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(ParticleRun, ShortRunEndsInACompletedRunFileWithItsProvenance) {
  testing::ScratchDir dir;
  ParticleRunOptions opt;
  opt.scene_path = kScene;
  opt.overrides = {"run.duration=0.2"};
  opt.output = dir.file("run.h5");
  opt.quiet = true;
  ASSERT_EQ(runParticles(opt, "granwave simulate (test)", "test-version"), kExitSuccess);
  const H5mdReader run(opt.output);
  EXPECT_TRUE(run.completed());
  EXPECT_GT(run.frameCount(), 0u);
  EXPECT_EQ(run.provenance().program_version, "test-version");
  EXPECT_EQ(run.provenance().command_line, "granwave simulate (test)");
  EXPECT_NEAR(run.observable("center_of_mass_height").time.back(), 0.2, 1e-9);
}

// A study keeps only the first and the last frame of a run it does not read the trajectory of
// (studies/runner/RunCache.cpp): a stride of lastRecordStep must put the last record into the
// trajectory, whatever the duration (a whole number of records or not, driven or not).
TEST(ParticleRun, StrideOfTheLastRecordStepKeepsTheFirstAndTheLastRecordAsFrames) {
  for (const char* duration : {"0.2", "0.2037"}) {
    for (const char* frequency : {"10", "0"}) {
      testing::ScratchDir dir;
      ParticleRunOptions opt;
      opt.scene_path = kScene;
      opt.overrides = {std::string("run.duration=") + duration,
                       std::string("drive.frequency=") + frequency};
      const std::uint64_t last = lastRecordStep(parseSceneFile(kScene, opt.overrides));
      opt.overrides.push_back("run.trajectory_stride=" + std::to_string(last));
      opt.output = dir.file("run.h5");
      opt.quiet = true;
      ASSERT_EQ(runParticles(opt, "granwave simulate (test)", "test-version"), kExitSuccess);
      const H5mdReader run(opt.output);
      SCOPED_TRACE(std::string(duration) + " s at " + frequency + " Hz");
      EXPECT_EQ(run.recordCount(), last + 1);
      ASSERT_EQ(run.frameCount(), 2u);
      EXPECT_EQ(run.frame(1).step, last);
    }
  }
}

TEST(ParticleRun, OutputOverItsSceneIsRefusedBeforeAnyWork) {
  testing::ScratchDir dir;
  const std::string scene = dir.file("scene.toml");
  std::filesystem::copy_file(kScene, scene);
  ParticleRunOptions opt;
  opt.scene_path = scene;
  opt.output = scene;
  opt.quiet = true;
  EXPECT_THROW(ParticleRun run(opt), files::PathError);
  EXPECT_EQ(slurp(scene), slurp(kScene));
}

}  // namespace granwave
