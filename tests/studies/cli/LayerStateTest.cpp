// The classifiers on whole simulated layers of known state: the paper's dry layer is
// a crystal at Gamma = 2, f = 20 Hz (a thin, dense, barely lifted packing of monodisperse disks
// orders hexagonally) and fluidized (liquid-like) at Gamma = 4, f = 10 Hz (the paper's scene,
// Fig. 2). The expected states come from the paper's stability diagram (Fig. 3) at those points.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "h5/File.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace {

std::string classify(const granwave::testing::ScratchDir& dir, const std::string& set) {
  const std::string fields = dir.file("fields.h5");
  const std::string cmd = std::string("'") + GRANWAVE_BINARY + "' simulate '" +
                          GRANWAVE_SOURCE_DIR + "/scenes/paper-dry.toml' --no-output -q " + set +
                          " --fields '" + fields + "' > /dev/null 2>&1";
  if (std::system(cmd.c_str()) != 0) return "simulate failed";
  const granwave::h5::File f = granwave::h5::File::openReadOnly(fields);
  if (f.readAttribute<std::int64_t>("/patterns", "available") == 0) return "not classified";
  return f.readStringAttribute("/patterns", "state");
}

TEST(LayerState, DryLayerAtGamma2And20HzIsCrystal) {
  granwave::testing::ScratchDir dir;
  EXPECT_EQ(classify(dir, "--set drive.frequency=20 --set drive.gamma=2 --set run.duration=3"),
            "crystal");
}

TEST(LayerState, DryLayerAtGamma4And10HzIsLiquidLike) {
  granwave::testing::ScratchDir dir;
  EXPECT_EQ(classify(dir, "--set run.duration=6"), "liquid-like");
}

}  // namespace
