#include "h5/Writeback.hpp"

#include <fcntl.h>
#include <hdf5.h>

namespace granwave::h5 {

void startWriteback(const File& file) {
  const hid_t access = H5Fget_access_plist(file.id());
  if (access < 0) return;
  const bool sec2 = H5Pget_driver(access) == H5FD_SEC2;
  H5Pclose(access);
  void* handle = nullptr;
  if (!sec2 || H5Fget_vfd_handle(file.id(), H5P_DEFAULT, &handle) < 0 || !handle) return;
  (void)::sync_file_range(*static_cast<int*>(handle), 0, 0, SYNC_FILE_RANGE_WRITE);
}

}  // namespace granwave::h5
