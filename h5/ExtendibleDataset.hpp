#pragma once
// A chunked dataset [rows][row_shape...] with an unlimited first axis, appended to row by
// row: the layout of H5MD time series (one row per recorded frame). Obtained from
// File::createExtendible (or reopened by File::openExtendible); the File must outlive it.
#include <cstddef>
#include <span>
#include <string>
#include <utility>

#include "h5/Handle.hpp"
#include "h5/Types.hpp"

namespace granwave::h5 {

class File;

template <Element T>
class ExtendibleDataset {
 public:
  ExtendibleDataset() = default;

  // Appends whole rows: `values.size()` must be a multiple of rowSize().
  void append(std::span<const T> values);
  void appendRow(std::span<const T> row) { append(row); }

  std::size_t rows() const { return rows_; }
  std::size_t rowSize() const { return elementCount(row_shape_); }
  const Shape& rowShape() const { return row_shape_; }
  const std::string& path() const { return path_; }
  bool isOpen() const { return dataset_.valid(); }
  void close() { dataset_.reset(); }

 private:
  friend class File;
  ExtendibleDataset(Handle dataset, std::string file, std::string path, Shape row_shape,
                    std::size_t rows = 0)
      : dataset_(std::move(dataset)),
        file_(std::move(file)),
        path_(std::move(path)),
        row_shape_(std::move(row_shape)),
        rows_(rows) {}

  Handle dataset_;
  std::string file_;  // for messages
  std::string path_;
  Shape row_shape_;
  std::size_t rows_ = 0;
};

}  // namespace granwave::h5
