// One particle run as `granwave simulate` makes it, driven directly: a short run of the paper's
// dry scene ends in a completed run file that names the program and command that made it, and
// an output that would overwrite the scene is refused before any work, the scene untouched.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "files/OutputPath.hpp"
#include "particles/H5mdReader.hpp"
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
