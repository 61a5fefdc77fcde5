#pragma once
// Move-only owner of one HDF5 identifier. HDF5 has a different close function per kind of
// object (H5Fclose, H5Gclose, H5Dclose, ...); the handle remembers which one applies, so
// every early return and exception path closes what it opened.
#include <hdf5.h>

#include <utility>

namespace granwave::h5 {

class Handle {
 public:
  using CloseFn = herr_t (*)(hid_t);

  Handle() = default;
  Handle(hid_t id, CloseFn close) noexcept : id_(id), close_(close) {}
  ~Handle() { reset(); }

  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(other.release()), close_(other.close_) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      close_ = other.close_;
      id_ = other.release();
    }
    return *this;
  }

  hid_t get() const noexcept { return id_; }
  bool valid() const noexcept { return id_ >= 0; }

  // Closes now and reports HDF5's status (negative on failure); used where a failed close
  // matters, e.g. a file whose last buffered data could not be written.
  herr_t close() noexcept {
    herr_t status = 0;
    if (id_ >= 0 && close_ != nullptr) status = close_(id_);
    id_ = H5I_INVALID_HID;
    return status;
  }
  void reset() noexcept { (void)close(); }
  hid_t release() noexcept { return std::exchange(id_, H5I_INVALID_HID); }

 private:
  hid_t id_ = H5I_INVALID_HID;
  CloseFn close_ = nullptr;
};

// One factory per object kind, so call sites read as what they hold.
inline Handle fileHandle(hid_t id) { return {id, H5Fclose}; }
inline Handle groupHandle(hid_t id) { return {id, H5Gclose}; }
inline Handle datasetHandle(hid_t id) { return {id, H5Dclose}; }
inline Handle dataspaceHandle(hid_t id) { return {id, H5Sclose}; }
inline Handle datatypeHandle(hid_t id) { return {id, H5Tclose}; }
inline Handle attributeHandle(hid_t id) { return {id, H5Aclose}; }
inline Handle propertyListHandle(hid_t id) { return {id, H5Pclose}; }
inline Handle objectHandle(hid_t id) { return {id, H5Oclose}; }

}  // namespace granwave::h5
