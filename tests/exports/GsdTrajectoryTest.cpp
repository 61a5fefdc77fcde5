// The GSD writer against the file layer's specification (gsd.readthedocs.io, "File layer"):
// the header, an index sorted by frame and then name id that ends with a zeroed entry and points
// inside the file, a namelist of 0-terminated names ended by an empty one, and chunks holding
// the hoomd schema's values. (gsd's own reader and MDAnalysis read real exports in
// tests/studies/cli/export_in_readers.py.)
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "exports/TrajectoryWriter.hpp"
#include "tests/exports/TestFrames.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

struct Entry {
  std::uint64_t frame, n;
  std::int64_t location;
  std::uint32_t m;
  std::uint16_t id;
  std::uint8_t type, flags;
};

template <class T>
T at(const std::string& bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

class GsdFile {
 public:
  explicit GsdFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    bytes = ss.str();
    for (std::size_t offset = at<std::uint64_t>(bytes, 8);; offset += 32) {
      const Entry e{at<std::uint64_t>(bytes, offset),      at<std::uint64_t>(bytes, offset + 8),
                    at<std::int64_t>(bytes, offset + 16),  at<std::uint32_t>(bytes, offset + 24),
                    at<std::uint16_t>(bytes, offset + 28), at<std::uint8_t>(bytes, offset + 30),
                    at<std::uint8_t>(bytes, offset + 31)};
      if (e.location == 0) break;
      index.push_back(e);
    }
    const std::size_t names_at = at<std::uint64_t>(bytes, 24);
    for (std::size_t p = names_at; bytes[p] != '\0'; p += names.back().size() + 1)
      names.emplace_back(bytes.c_str() + p);
  }

  // The values of chunk `name` in `frame`, as T.
  template <class T>
  std::vector<T> chunk(std::uint64_t frame, const std::string& name) const {
    for (const Entry& e : index) {
      if (e.frame != frame || names.at(e.id) != name) continue;
      std::vector<T> out(e.n * e.m);
      std::memcpy(out.data(), bytes.data() + e.location, out.size() * sizeof(T));
      return out;
    }
    return {};
  }

  std::string bytes;
  std::vector<Entry> index;
  std::vector<std::string> names;
};

TEST(GsdTrajectory, HeaderNamesTheFileLayerAndTheHoomdSchema) {
  testing::ScratchDir dir;
  testing::writeAll(TrajectoryFormat::Gsd, dir.file("t.gsd"));
  const GsdFile f(dir.file("t.gsd"));
  EXPECT_EQ(at<std::uint64_t>(f.bytes, 0), 0x65DF65DF65DF65DFull);
  EXPECT_EQ(at<std::uint32_t>(f.bytes, 40), (1u << 16) | 4u);  // schema 1.4
  EXPECT_EQ(at<std::uint32_t>(f.bytes, 44), 2u << 16);         // file layer 2.0
  EXPECT_STREQ(f.bytes.c_str() + 48, "granwave 9.8.7");
  EXPECT_STREQ(f.bytes.c_str() + 112, "hoomd");
  // The index block holds the entries and the zeroed one; the namelist whole 64-byte segments.
  EXPECT_EQ(at<std::uint64_t>(f.bytes, 16), f.index.size() + 1);
  const std::uint64_t names_at = at<std::uint64_t>(f.bytes, 24);
  EXPECT_EQ(names_at + 64 * at<std::uint64_t>(f.bytes, 32), f.bytes.size());
}

TEST(GsdTrajectory, IndexIsSortedByFrameThenNameAndPointsInsideTheFile) {
  testing::ScratchDir dir;
  testing::writeAll(TrajectoryFormat::Gsd, dir.file("t.gsd"));
  const GsdFile f(dir.file("t.gsd"));
  ASSERT_EQ(f.names.size(), 13u);
  ASSERT_FALSE(f.index.empty());
  const std::map<std::uint8_t, std::size_t> size{{1, 1}, {3, 4}, {4, 8}, {5, 1}, {9, 4}, {10, 8}};
  for (std::size_t i = 0; i < f.index.size(); ++i) {
    const Entry& e = f.index[i];
    EXPECT_LT(e.id, f.names.size());
    EXPECT_EQ(e.flags, 0);
    EXPECT_GT(e.m, 0u);
    ASSERT_TRUE(size.count(e.type)) << int(e.type);
    EXPECT_LE(static_cast<std::size_t>(e.location) + e.n * e.m * size.at(e.type), f.bytes.size());
    if (i > 0) {
      const Entry& p = f.index[i - 1];
      EXPECT_TRUE(p.frame < e.frame || (p.frame == e.frame && p.id < e.id)) << i;
    }
  }
  EXPECT_EQ(f.index.back().frame, 1u);
}

TEST(GsdTrajectory, ChunksHoldTheFramesInTheContainersCentredFrame) {
  testing::ScratchDir dir;
  testing::writeAll(TrajectoryFormat::Gsd, dir.file("t.gsd"));
  const GsdFile f(dir.file("t.gsd"));
  EXPECT_EQ(f.chunk<std::uint64_t>(1, "configuration/step"), std::vector<std::uint64_t>{10});
  EXPECT_EQ(f.chunk<float>(0, "configuration/box"),
            (std::vector<float>{0.06f, 0.002f, 0.06f, 0, 0, 0}));
  EXPECT_TRUE(f.chunk<float>(1, "configuration/box").empty());  // frame 0's holds
  EXPECT_EQ(f.chunk<std::uint32_t>(0, "particles/N"), std::vector<std::uint32_t>{2});
  EXPECT_STREQ(f.chunk<char>(0, "particles/types").data(), "disk");
  // Frame 1: x - Lx/2, 0, z - z_b - Lz/2 with z_b = 0.005.
  const std::vector<float> position = f.chunk<float>(1, "particles/position");
  ASSERT_EQ(position.size(), 6u);
  EXPECT_EQ(position[0], static_cast<float>(0.011 - 0.03));
  EXPECT_EQ(position[1], 0.0f);
  EXPECT_EQ(position[5], static_cast<float>(0.041 - (0.005 + 0.03)));
  EXPECT_EQ(f.chunk<float>(1, "particles/velocity")[3], -0.5f);
  EXPECT_EQ(f.chunk<double>(1, "log/particles/angular_velocity")[4], -14.0);
  EXPECT_EQ(f.chunk<double>(1, "log/time"), std::vector<double>{0.01});
  EXPECT_EQ(f.chunk<double>(1, "log/plate_height"), std::vector<double>{0.005});
  EXPECT_EQ(f.chunk<float>(0, "particles/mass"), (std::vector<float>(2, 1.08e-5f)));
}

}  // namespace
}  // namespace granwave
