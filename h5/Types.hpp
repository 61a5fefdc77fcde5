#pragma once
// Element types the HDF5 layer stores, their HDF5 memory types, and dataset shapes.
// Three numeric types are enough for granwave (values, steps, counters); keeping the set
// closed lets the templates live in .cpp files with explicit instantiations.
#include <hdf5.h>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace granwave::h5 {

template <class T>
concept Element =
    std::same_as<T, double> || std::same_as<T, std::int64_t> || std::same_as<T, std::uint64_t>;

template <Element T>
hid_t nativeType() {
  if constexpr (std::same_as<T, double>) {
    return H5T_NATIVE_DOUBLE;
  } else if constexpr (std::same_as<T, std::int64_t>) {
    return H5T_NATIVE_INT64;
  } else {
    return H5T_NATIVE_UINT64;
  }
}

// The type written to disk: fixed little-endian standard types, so a file means the same
// on every machine (HDF5 converts on read).
template <Element T>
hid_t fileType() {
  if constexpr (std::same_as<T, double>) {
    return H5T_IEEE_F64LE;
  } else if constexpr (std::same_as<T, std::int64_t>) {
    return H5T_STD_I64LE;
  } else {
    return H5T_STD_U64LE;
  }
}

// Extents of a dataset, slowest-varying first (C order, as HDF5 and numpy store them).
using Shape = std::vector<std::size_t>;

// How a whole dataset is stored (File::writeDataset).
enum class Storage { contiguous, compressed };

// In an expected shape, matches any extent (e.g. the number of frames).
inline constexpr std::size_t kAnyExtent = std::numeric_limits<std::size_t>::max();

// "[5][7][3]" for messages; "*" for kAnyExtent, "[]" for a scalar.
inline std::string shapeString(const Shape& shape) {
  if (shape.empty()) return "[]";
  std::string text;
  for (std::size_t extent : shape) {
    // append() rather than "[" + ...: GCC 12 warns falsely (-Wrestrict) on the latter.
    text.append("[").append(extent == kAnyExtent ? "*" : std::to_string(extent)).append("]");
  }
  return text;
}

inline std::size_t elementCount(const Shape& shape) {
  std::size_t count = 1;
  for (std::size_t extent : shape) count *= extent;
  return count;
}

}  // namespace granwave::h5
