#include "h5/Dataspace.hpp"

#include <vector>

#include "h5/ErrorStack.hpp"

namespace granwave::h5 {
namespace {

std::vector<hsize_t> toHsize(const Shape& shape) {
  std::vector<hsize_t> dims;
  for (std::size_t extent : shape) dims.push_back(extent == kAnyExtent ? H5S_UNLIMITED : extent);
  return dims;
}

}  // namespace

Handle makeDataspace(const Shape& shape, const std::string& file) {
  return makeDataspace(shape, shape, file);
}

Handle makeDataspace(const Shape& shape, const Shape& max_shape, const std::string& file) {
  if (shape.empty()) return dataspaceHandle(check(H5Screate(H5S_SCALAR), file, "no dataspace"));
  const std::vector<hsize_t> dims = toHsize(shape);
  const std::vector<hsize_t> max_dims = toHsize(max_shape);
  hid_t id = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max_dims.data());
  return dataspaceHandle(check(id, file, "cannot create dataspace " + shapeString(shape)));
}

Shape shapeOf(hid_t space, const std::string& file) {
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 0) fail(file, "cannot read dataspace rank");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space, dims.data(), nullptr) < 0) {
    fail(file, "cannot read dataspace extents");
  }
  return Shape(dims.begin(), dims.end());
}

}  // namespace granwave::h5
