#pragma once
// Two frames of two disks in the paper's box, with numbers that show which frame and which
// disk a written value came from.
#include <vector>

#include "exports/TrajectoryWriter.hpp"

namespace granwave::testing {

inline TrajectoryHeader twoDiskHeader() {
  TrajectoryHeader h;
  h.box = BoxInfo{0.06, 0.06, 0.002, true, false};
  h.diameter = 0.002;
  h.mass = 1.08e-5;
  h.version = "9.8.7";
  h.author = "tester";
  return h;
}

inline std::vector<Snapshot> twoDiskFrames() {
  std::vector<Snapshot> frames(2);
  for (int k = 0; k < 2; ++k) {
    Snapshot& s = frames[static_cast<std::size_t>(k)];
    s.step = static_cast<std::uint64_t>(10 * k);
    s.time = 0.01 * k;
    s.plate_height = 0.005 * k;
    s.x = {0.01 + k * 0.001, 0.03};
    s.z = {0.02, 0.04 + k * 0.001};
    s.vx = {0.5, -0.25 * (k + 1)};
    s.vz = {-1.5, 0.125};
    s.omega = {3.0, -7.0 * (k + 1)};
  }
  return frames;
}

inline void writeAll(TrajectoryFormat format, const std::string& path) {
  auto writer = makeTrajectoryWriter(format, path, path, twoDiskHeader());
  for (const Snapshot& s : twoDiskFrames()) writer->write(s);
  writer->close();
}

}  // namespace granwave::testing
