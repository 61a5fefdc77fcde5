#pragma once
// An open HDF5 file and the operations granwave needs on it: groups, attributes, whole
// datasets, chunked datasets that grow by rows, and shape-checked reads. Every failure is an
// H5Error naming the file and the object path. Object paths are absolute ("/a/b").
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "h5/ExtendibleDataset.hpp"
#include "h5/Handle.hpp"
#include "h5/Types.hpp"

namespace granwave::h5 {

class File {
 public:
  // Creates `path`, replacing any file there. `display_name` is what messages call the file
  // (AtomicFile passes its target, not the temporary name); empty means `path`.
  static File create(const std::string& path, const std::string& display_name = "");
  // Opens an existing file read-only. H5Error if it is missing, not HDF5, or damaged.
  static File openReadOnly(const std::string& path);
  // Opens an existing file for appending (a checkpoint's copy being continued).
  static File openReadWrite(const std::string& path, const std::string& display_name = "");

  File(File&&) noexcept = default;
  File& operator=(File&&) noexcept = default;
  ~File() = default;

  const std::string& name() const { return name_; }
  hid_t id() const { return file_.get(); }
  bool isOpen() const { return file_.valid(); }
  void flush();
  // Closes the file and every object still open in it (strong close degree), reporting a
  // failure to write back buffered data, which the destructor would have to swallow.
  void close();

  // Creates the group and any missing parents; an existing group is fine.
  void createGroup(const std::string& path);
  bool exists(const std::string& path) const;
  bool isGroup(const std::string& path) const;
  bool isDataset(const std::string& path) const;

  // Attributes of the group or dataset at `object` ("/" is the root). Writing replaces.
  template <Element T>
  void writeAttribute(const std::string& object, const std::string& name, T value);
  template <Element T>
  void writeArrayAttribute(const std::string& object, const std::string& name,
                           const std::vector<T>& values);
  void writeStringAttribute(const std::string& object, const std::string& name,
                            const std::string& value);
  void writeStringArrayAttribute(const std::string& object, const std::string& name,
                                 const std::vector<std::string>& values);
  bool hasAttribute(const std::string& object, const std::string& name) const;
  template <Element T>
  T readAttribute(const std::string& object, const std::string& name) const;
  template <Element T>
  std::vector<T> readArrayAttribute(const std::string& object, const std::string& name) const;
  std::string readStringAttribute(const std::string& object, const std::string& name) const;
  std::vector<std::string> readStringArrayAttribute(const std::string& object,
                                                    const std::string& name) const;

  // Whole datasets, written once. An empty shape writes a scalar. Compressed: in chunks of one
  // index of the first axis (a phase of a [phase][z][x] field), byte-shuffled and deflated,
  // HDF5's own filters that every HDF5 reader decodes (h5py, ParaView, MDAnalysis); fields of
  // a layer with vacuum above it shrink to about a third.
  template <Element T>
  void writeDataset(const std::string& path, const std::vector<T>& data, const Shape& shape,
                    Storage storage = Storage::contiguous);
  void writeStringDataset(const std::string& path, const std::string& text);

  // A chunked dataset of shape [0][row_shape...] that grows along its first axis; compressed:
  // its chunks shuffled and deflated as writeDataset's.
  template <Element T>
  ExtendibleDataset<T> createExtendible(const std::string& path, const Shape& row_shape,
                                        std::size_t chunk_rows,
                                        Storage storage = Storage::contiguous);

  // Reopens a dataset made by createExtendible, to append after its current rows.
  template <Element T>
  ExtendibleDataset<T> openExtendible(const std::string& path);

  Shape shape(const std::string& path) const;
  // Reads the whole dataset; `expected` (kAnyExtent matches anything) is checked first.
  template <Element T>
  std::vector<T> readDataset(const std::string& path) const;
  template <Element T>
  std::vector<T> readDataset(const std::string& path, const Shape& expected) const;
  // Reads rows [first, first + count) along the first axis (e.g. one trajectory frame).
  template <Element T>
  std::vector<T> readRows(const std::string& path, std::size_t first, std::size_t count) const;
  std::string readStringDataset(const std::string& path) const;

 private:
  File(Handle file, std::string name) : file_(std::move(file)), name_(std::move(name)) {}

  Handle openObject(const std::string& path) const;   // group or dataset
  Handle openDataset(const std::string& path) const;  // "no dataset <path>" if absent
  Handle openAttribute(const std::string& object, const std::string& name) const;
  void writeRawAttribute(const std::string& object, const std::string& name, hid_t file_type,
                         hid_t memory_type, const Shape& shape, const void* data);
  template <Element T>
  std::vector<T> readNumericAttribute(const std::string& object, const std::string& name) const;
  [[noreturn]] void fail(const std::string& what) const;

  Handle file_;
  std::string name_;
};

// Property list that makes link creation add missing parent groups.
Handle intermediateGroupCreation();

}  // namespace granwave::h5
