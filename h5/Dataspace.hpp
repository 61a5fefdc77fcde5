#pragma once
// Conversions between Shape and HDF5 dataspaces, shared by attributes and datasets.
#include <string>

#include "h5/Handle.hpp"
#include "h5/Types.hpp"

namespace granwave::h5 {

// A simple dataspace of `shape` (scalar when empty), optionally with maximum extents.
Handle makeDataspace(const Shape& shape, const std::string& file);
Handle makeDataspace(const Shape& shape, const Shape& max_shape, const std::string& file);

// Current extents of a dataspace ({} for a scalar).
Shape shapeOf(hid_t space, const std::string& file);

}  // namespace granwave::h5
