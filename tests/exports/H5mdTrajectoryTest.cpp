// The H5MD export in the layout MDAnalysis's reader needs: the particle group "trajectory",
// lengths in nm and a unit on every value and time, the H5MD header naming granwave. (MDAnalysis
// itself reads a real export in tests/studies/cli/export_in_readers.py.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "exports/H5mdTrajectory.hpp"
#include "h5/File.hpp"
#include "tests/exports/TestFrames.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

TEST(H5mdTrajectory, LengthsAreInNanometresAndEveryValueHasItsUnit) {
  testing::ScratchDir dir;
  testing::writeAll(TrajectoryFormat::H5md, dir.file("t.h5md"));
  const h5::File f = h5::File::openReadOnly(dir.file("t.h5md"));
  EXPECT_EQ(f.readArrayAttribute<std::int64_t>("/h5md", "version"),
            (std::vector<std::int64_t>{1, 1}));
  EXPECT_EQ(f.readStringAttribute("/h5md/creator", "name"), "granwave");
  EXPECT_EQ(f.readStringAttribute("/h5md/creator", "version"), "9.8.7");
  EXPECT_EQ(f.readStringAttribute("/h5md/author", "name"), "tester");
  const std::string g = "/particles/trajectory/";
  EXPECT_EQ(f.readAttribute<std::int64_t>(g + "box", "dimension"), 3);
  for (const auto& [element, unit] :
       std::vector<std::pair<std::string, std::string>>{{g + "box/edges", "nm"},
                                                        {g + "position", "nm"},
                                                        {g + "velocity", "m s-1"},
                                                        {g + "angular_velocity", "rad s-1"},
                                                        {"/observables/plate_height", "nm"}}) {
    EXPECT_EQ(f.readStringAttribute(element + "/value", "unit"), unit) << element;
    EXPECT_EQ(f.readStringAttribute(element + "/time", "unit"), "s") << element;
    EXPECT_EQ(f.shape(element + "/step").at(0), 2u) << element;
  }
  const std::vector<double> position = f.readRows<double>(g + "position/value", 1, 1);
  EXPECT_DOUBLE_EQ(position.at(0), 0.011 * 1e9);
  EXPECT_DOUBLE_EQ(position.at(5), 0.041 * 1e9);
  EXPECT_EQ(f.readRows<double>(g + "velocity/value", 1, 1).at(3), -0.5);
  EXPECT_DOUBLE_EQ(f.readDataset<double>("/observables/plate_height/value").at(1), 0.005 * 1e9);
}

}  // namespace
}  // namespace granwave
