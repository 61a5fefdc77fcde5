#include "h5/ExtendibleDataset.hpp"

#include <cstdint>
#include <vector>

#include "h5/Dataspace.hpp"
#include "h5/ErrorStack.hpp"
#include "h5/H5Error.hpp"

namespace granwave::h5 {

template <Element T>
void ExtendibleDataset<T>::append(std::span<const T> values) {
  if (!dataset_.valid()) throw H5Error(file_ + ": " + path_ + " is closed");
  const std::size_t row_size = rowSize();
  if (row_size == 0 || values.size() % row_size != 0) {
    throw H5Error(file_ + ": " + path_ + ": " + std::to_string(values.size()) +
                  " values are not whole rows of " + shapeString(row_shape_));
  }
  const std::size_t count = values.size() / row_size;
  if (count == 0) return;

  std::vector<hsize_t> extent{rows_ + count}, start{rows_}, block{count};
  for (std::size_t extent_i : row_shape_) {
    extent.push_back(extent_i);
    start.push_back(0);
    block.push_back(extent_i);
  }
  if (H5Dset_extent(dataset_.get(), extent.data()) < 0) fail(file_, "cannot extend " + path_);
  Handle space = dataspaceHandle(check(H5Dget_space(dataset_.get()), file_, "no dataspace"));
  if (H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr, block.data(),
                          nullptr) < 0) {
    fail(file_, "cannot select new rows of " + path_);
  }
  Handle memory = makeDataspace(Shape(block.begin(), block.end()), file_);
  if (H5Dwrite(dataset_.get(), nativeType<T>(), memory.get(), space.get(), H5P_DEFAULT,
               values.data()) < 0) {
    fail(file_, "cannot append to " + path_);
  }
  rows_ += count;
}

template class ExtendibleDataset<double>;
template class ExtendibleDataset<std::int64_t>;
template class ExtendibleDataset<std::uint64_t>;

}  // namespace granwave::h5
