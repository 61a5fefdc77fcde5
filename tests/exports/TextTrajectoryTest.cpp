// The text formats line by line: extended XYZ (ase.io.extxyz's layout) and the LAMMPS dump
// ("dump custom" as LAMMPS writes it: nine header lines, ids from 1, the box where the container
// is). The real readers read real exports in tests/studies/cli/export_in_readers.py.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "exports/TrajectoryWriter.hpp"
#include "tests/exports/TestFrames.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(TextTrajectory, ExtendedXyzHasTheCellTimeAndEveryDisksState) {
  testing::ScratchDir dir;
  testing::writeAll(TrajectoryFormat::ExtendedXyz, dir.file("t.extxyz"));
  const std::string text = slurp(dir.file("t.extxyz"));
  const std::string frame1 =
      "2\n"
      "Lattice=\"0.06 0 0 0 0.002 0 0 0 0.06\" Properties=species:S:1:pos:R:3:velocities:R:3:"
      "angular_velocity:R:3:radius:R:1 Time=0.01 step=10 plate_height=0.005 units=SI "
      "pbc=\"T F F\"\n"
      "X 0.011 0 0.02 0.5 0 -1.5 0 3 0 0.001\n"
      "X 0.03 0 0.041 -0.5 0 0.125 0 -14 0 0.001\n";
  ASSERT_GE(text.size(), frame1.size());
  EXPECT_EQ(text.substr(text.size() - frame1.size()), frame1);
}

TEST(TextTrajectory, LammpsDumpHasNineHeaderLinesAndTheContainerAtThePlate) {
  testing::ScratchDir dir;
  testing::writeAll(TrajectoryFormat::LammpsDump, dir.file("t.lammpstrj"));
  const std::string text = slurp(dir.file("t.lammpstrj"));
  const std::string frame1 =
      "ITEM: TIMESTEP\n10\nITEM: NUMBER OF ATOMS\n2\n"
      "ITEM: BOX BOUNDS pp ff ff\n0 0.06\n-0.001 0.001\n0.005 0.065\n"
      "ITEM: ATOMS id type mass radius x y z vx vy vz omegax omegay omegaz\n"
      "1 1 1.08e-05 0.001 0.011 0 0.02 0.5 0 -1.5 0 3 0\n"
      "2 1 1.08e-05 0.001 0.03 0 0.041 -0.5 0 0.125 0 -14 0\n";
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2 * (9 + 2));
  EXPECT_EQ(text.substr(0, 17), "ITEM: TIMESTEP\n0\n");
  ASSERT_GE(text.size(), frame1.size());
  EXPECT_EQ(text.substr(text.size() - frame1.size()), frame1);
}

}  // namespace
}  // namespace granwave
