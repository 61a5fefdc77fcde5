// h5::File: round trips of datasets and attributes, and one-line H5Errors (naming the file
// and the object) for missing objects, wrong shapes, and files that are not HDF5 or are
// damaged.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "h5/H5Error.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave::h5 {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;

// Runs `action`, expects an H5Error, and returns its message.
template <class Action>
std::string h5ErrorOf(Action action) {
  try {
    action();
  } catch (const H5Error& error) {
    return error.what();
  }
  ADD_FAILURE() << "no H5Error thrown";
  return {};
}

TEST(File, DatasetsRoundTrip) {
  testing::ScratchDir dir;
  const std::string path = dir.file("data.h5");
  const std::vector<double> doubles{0.1,  -2.5, 1e-310, std::numeric_limits<double>::max(),
                                    -0.0, 3.0};
  const std::vector<std::int64_t> ints{-1, 0, std::numeric_limits<std::int64_t>::min(), 7};
  const std::vector<std::uint64_t> unsigneds{std::numeric_limits<std::uint64_t>::max(), 1, 2, 3};
  const std::string text = "[particles]\ncount = 300\nname = \"π ≈ 3.14\"\n";
  {
    File file = File::create(path);
    file.writeDataset("/a/b/doubles", doubles, {2, 3});
    file.writeDataset("/ints", ints, {4});
    file.writeDataset("/a/unsigneds", unsigneds, {2, 2});
    file.writeDataset<double>("/scalar", {42.5}, {});
    file.writeStringDataset("/text", text);
    file.close();
  }
  const File file = File::openReadOnly(path);
  EXPECT_TRUE(file.isGroup("/a/b"));
  EXPECT_TRUE(file.isDataset("/a/b/doubles"));
  EXPECT_FALSE(file.isDataset("/a/b"));
  EXPECT_FALSE(file.exists("/a/nothing/deeper"));
  EXPECT_EQ(file.shape("/a/b/doubles"), (Shape{2, 3}));
  const std::vector<double> read = file.readDataset<double>("/a/b/doubles", {2, kAnyExtent});
  ASSERT_EQ(read.size(), doubles.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(read[i]), std::bit_cast<std::uint64_t>(doubles[i]));
  }
  EXPECT_EQ(file.readDataset<std::int64_t>("/ints"), ints);
  EXPECT_EQ(file.readDataset<std::uint64_t>("/a/unsigneds", {2, 2}), unsigneds);
  EXPECT_EQ(file.readDataset<double>("/scalar", {}), std::vector<double>{42.5});
  EXPECT_EQ(file.readRows<double>("/a/b/doubles", 1, 1),
            (std::vector<double>{doubles[3], -0.0, 3.0}));
  EXPECT_EQ(file.readStringDataset("/text"), text);
}

TEST(File, AttributesRoundTrip) {
  testing::ScratchDir dir;
  const std::string path = dir.file("attributes.h5");
  {
    File file = File::create(path);
    file.createGroup("/g/h");
    file.writeDataset<double>("/g/values", {1, 2}, {2});
    file.writeStringAttribute("/", "title", "granwave");
    file.writeAttribute("/g/h", "pi", 3.141592653589793);
    file.writeAttribute<std::int64_t>("/g/h", "count", -12);
    file.writeAttribute<std::uint64_t>("/g/h", "seed", std::numeric_limits<std::uint64_t>::max());
    file.writeArrayAttribute<std::int64_t>("/g", "version", {1, 1});
    file.writeStringArrayAttribute("/g/values", "boundary", {"periodic", "", "none"});
    file.writeStringAttribute("/g/values", "unit", "m");
    file.writeStringAttribute("/g/values", "unit", "m/s");  // replaces
    file.close();
  }
  const File file = File::openReadOnly(path);
  EXPECT_EQ(file.readStringAttribute("/", "title"), "granwave");
  EXPECT_EQ(file.readAttribute<double>("/g/h", "pi"), 3.141592653589793);
  EXPECT_EQ(file.readAttribute<std::int64_t>("/g/h", "count"), -12);
  EXPECT_EQ(file.readAttribute<std::uint64_t>("/g/h", "seed"),
            std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(file.readArrayAttribute<std::int64_t>("/g", "version"),
            (std::vector<std::int64_t>{1, 1}));
  EXPECT_EQ(file.readStringArrayAttribute("/g/values", "boundary"),
            (std::vector<std::string>{"periodic", "", "none"}));
  EXPECT_EQ(file.readStringAttribute("/g/values", "unit"), "m/s");
  EXPECT_TRUE(file.hasAttribute("/g/h", "pi"));
  EXPECT_FALSE(file.hasAttribute("/g/h", "nope"));
  EXPECT_FALSE(file.hasAttribute("/missing", "pi"));
  EXPECT_THAT(h5ErrorOf([&] { file.readAttribute<double>("/g", "version"); }),
              HasSubstr("holds 2 values, expected one"));
}

TEST(File, ExtendibleDatasetGrowsByRows) {
  testing::ScratchDir dir;
  const std::string path = dir.file("series.h5");
  {
    File file = File::create(path);
    ExtendibleDataset<double> rows = file.createExtendible<double>("/s/value", {2}, 4);
    ExtendibleDataset<std::int64_t> steps = file.createExtendible<std::int64_t>("/s/step", {}, 4);
    for (int i = 0; i < 7; ++i) {
      const std::vector<double> row{1.0 * i, -1.0 * i};
      rows.append(row);
      const std::int64_t step[] = {i};
      steps.append(step);
    }
    rows.append(std::vector<double>{10, 11, 12, 13});  // two rows at once
    EXPECT_EQ(rows.rows(), 9u);
    EXPECT_THAT(h5ErrorOf([&] {
                  rows.append(std::vector<double>{1, 2, 3});
                }),
                AllOf(HasSubstr(path), HasSubstr("/s/value"), HasSubstr("not whole rows")));
    file.close();
  }
  const File file = File::openReadOnly(path);
  EXPECT_EQ(file.shape("/s/value"), (Shape{9, 2}));
  EXPECT_EQ(file.readDataset<std::int64_t>("/s/step"),
            (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(file.readRows<double>("/s/value", 7, 2), (std::vector<double>{10, 11, 12, 13}));
  EXPECT_THAT(h5ErrorOf([&] { file.readRows<double>("/s/value", 8, 2); }),
              AllOf(HasSubstr(path), HasSubstr("outside /s/value")));
}

TEST(File, ReadsFixedLengthStringsWrittenByOtherTools) {
  testing::ScratchDir dir;
  const std::string path = dir.file("fixed.h5");
  {
    // As written by h5py for numpy bytes arrays: fixed width, null-padded, no terminator
    // when a string fills its width.
    hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, 8);
    H5Tset_strpad(type, H5T_STR_NULLPAD);
    hsize_t three = 3;
    hid_t space = H5Screate_simple(1, &three, nullptr);
    hid_t attribute = H5Acreate2(file, "boundary", type, space, H5P_DEFAULT, H5P_DEFAULT);
    const char data[] = "periodicnone\0\0\0\0none\0\0\0\0";
    H5Awrite(attribute, type, data);
    H5Aclose(attribute);
    H5Sclose(space);
    H5Tclose(type);
    H5Fclose(file);
  }
  const File file = File::openReadOnly(path);
  EXPECT_EQ(file.readStringArrayAttribute("/", "boundary"),
            (std::vector<std::string>{"periodic", "none", "none"}));
}

TEST(File, MissingDatasetNamesFileAndPath) {
  testing::ScratchDir dir;
  const std::string path = dir.file("RUN.h5");
  File::create(path).close();
  const File file = File::openReadOnly(path);
  const std::string message =
      h5ErrorOf([&] { file.readDataset<double>("/particles/all/position/value"); });
  EXPECT_EQ(message, path + ": no dataset /particles/all/position/value");
  EXPECT_THAT(h5ErrorOf([&] { file.readStringAttribute("/h5md", "version"); }),
              AllOf(HasSubstr(path), HasSubstr("/h5md")));
}

TEST(File, WrongShapeOrTypeIsAnError) {
  testing::ScratchDir dir;
  const std::string path = dir.file("shapes.h5");
  {
    File file = File::create(path);
    file.writeDataset<double>("/v", {1, 2, 3, 4, 5, 6}, {2, 3});
    file.writeStringDataset("/text", "hello");
    EXPECT_THAT(h5ErrorOf([&] {
                  file.writeDataset<double>("/w", {1, 2}, {3});
                }),
                HasSubstr("do not fill shape [3]"));
    file.close();
  }
  const File file = File::openReadOnly(path);
  EXPECT_EQ(h5ErrorOf([&] {
              file.readDataset<double>("/v", {3, 3});
            }),
            path + ": /v has shape [2][3], expected [3][3]");
  EXPECT_EQ(h5ErrorOf([&] { file.readDataset<double>("/text"); }), path + ": /text is not numeric");
  EXPECT_THAT(h5ErrorOf([&] { file.readStringDataset("/v"); }),
              HasSubstr("is not a single string"));
}

TEST(File, MissingFileIsAnError) {
  testing::ScratchDir dir;
  const std::string path = dir.file("absent.h5");
  EXPECT_EQ(h5ErrorOf([&] { File::openReadOnly(path); }), path + ": no such file");
}

TEST(File, NonHdf5FileIsAnError) {
  testing::ScratchDir dir;
  const std::string path = dir.file("scene.toml");
  std::ofstream(path) << "[particles]\ncount = 300\n";
  EXPECT_EQ(h5ErrorOf([&] { File::openReadOnly(path); }), path + ": not an HDF5 file");
}

TEST(File, TruncatedFileIsAnErrorNotACrash) {
  testing::ScratchDir dir;
  const std::string path = dir.file("truncated.h5");
  {
    File file = File::create(path);
    file.writeDataset("/big", std::vector<double>(20000, 1.5), {20000});
    file.writeStringAttribute("/big", "unit", "m");
    file.close();
  }
  std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
  const std::string message = h5ErrorOf([&] {
    const File file = File::openReadOnly(path);
    (void)file.readDataset<double>("/big");  // in case opening alone does not notice
  });
  EXPECT_THAT(message, AllOf(HasSubstr(path + ": "), Not(HasSubstr("\n"))));
}

TEST(File, CreateInMissingDirectoryNamesTheFile) {
  testing::ScratchDir dir;
  const std::string path = dir.file("no/such/dir/out.h5");
  EXPECT_THAT(h5ErrorOf([&] { File::create(path); }),
              AllOf(HasSubstr(path + ": cannot create file"), Not(HasSubstr("\n"))));
}

}  // namespace
}  // namespace granwave::h5
